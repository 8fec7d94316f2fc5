#pragma once
// The `collision` analyzer: on the frames of a head-on collision of two spheres in free
// flight (no walls touched; gravity off), emitted every time step, the measured contact time
// and restitution coefficient beside the linear law's analytic values for the pair's
// masses (density of its species times volume) and the given k_n and gamma_n, with their
// relative errors.
#include "collision_tracker.hpp"
#include "granpipe/plugin.hpp"

namespace granpipe::collision {

Schema schema();

// The pair's state in a frame of two spheres with velocities; throws InputError starting
// with `where` for any other number of particles or a sphere touching a wall.
PairState pair_state(const Frame& frame, const std::string& where);

class CollisionAnalyzer : public Analyzer {
 public:
  explicit CollisionAnalyzer(const PluginContext& ctx);
  FrameContent needs() const override;
  void consume(const Frame& frame, FrameCache& cache) override;
  void finish(Results& results) override;

 private:
  double kn_, gamma_n_;
  std::vector<double> density_;
  std::string density_param_;
  double m_eff_ = 0.0;
  long frames_ = 0;
  CollisionTracker tracker_;
};

}  // namespace granpipe::collision
