#pragma once
// The `collision` analyzer: on the frames of a head-on collision of two spheres in free
// flight (no walls touched; gravity off), emitted every time step, the measured contact time
// and restitution coefficient beside the linear law's analytic values for the pair's
// masses (density of its species times volume) and the given k_n and gamma_n, with their
// relative errors.
//
// The analytic values are only the source's when the analyzer's parameters are: frames
// must come every time step (consecutive steps; a gap is refused), with the contact forces;
// the stiffness and damping those forces show must be the given k_n and gamma_n m_eff within
// kStiffnessTolerance and kDampingTolerance (stiffness_fit.hpp), and the pair's relative
// momentum must change by its contact's impulse alone, with m_eff from the given densities
// (impulse_balance.hpp), or the run is refused.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "collision_tracker.hpp"
#include "granpipe/plugin.hpp"
#include "impulse_balance.hpp"
#include "stiffness_fit.hpp"

namespace granpipe::collision {

Schema schema();

// The pair's state in a frame of two spheres with velocities; throws InputError starting
// with `where` for any other number of particles or a sphere touching a wall.
PairState pair_state(const Frame& frame, const std::string& where);

// The measured stiffness differs from the source's k_n by the time step's error (the
// collision of pipelines/dem_speed_vs_error.json: 0.1 % at dt = t_c/100, 0.6 % at t_c/20,
// 0.9 % at t_c/12.5); a wrong k_n is off by far more.
constexpr double kStiffnessTolerance = 0.02;
// The damping's, as a fraction of the critical damping (check_damping).
constexpr double kDampingTolerance = 0.01;
// What a line of the overlap and the normal velocity may leave of the normal forces (root
// mean squares) before a refusal names another law as the likely cause: up to 10^-8 for
// the linear law at dt = t_c/100 to t_c/12.5 in double precision (0.5-6 % at a dump's 6
// digits), 3-5 % for Hertz's.
constexpr double kLinearLawTolerance = 0.01;

class CollisionAnalyzer : public Analyzer {
 public:
  explicit CollisionAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override;
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  void check_step(const Frame& frame, const std::string& where);
  std::string law_hint() const;
  void check_stiffness() const;
  void check_damping() const;
  void check_impulse() const;

  double kn_, gamma_n_;
  std::vector<double> density_;
  std::string density_param_, kn_param_, gamma_n_param_;
  double m_eff_ = 0.0;
  long frames_ = 0;
  std::int64_t last_step_ = 0;
  CollisionTracker tracker_;
  StiffnessFit stiffness_;
  ImpulseBalance impulse_;
};

}  // namespace granpipe::collision
