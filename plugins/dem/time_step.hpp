#pragma once
// Is the time step small enough? The contact time t_c of every species pair and of every
// species against every wall (the shortest duration any part of the contact gives: Eq. (10)
// for the linear law, contact_parts.hpp), with the lightest particles of each species
// present (the light pairs decide: the Brazil-nut intruder is 220 times heavier than a
// small sphere), and the verdict on dt:
//   dt <= t_c / 20         fine
//   t_c/20 < dt <= t_c/10  warned
//   dt > t_c / 10          refused
// Measured for a linear head-on collision at e = 0.9 (tests/plugins/test_dem.cpp), the
// errors of the contact time and of e are: t_c/100: -0.06 %, -0.02 %; t_c/50: -0.12 %,
// +0.38 %; t_c/25: -0.28 %, +0.78 %; t_c/20: -0.37 %, +1.0 %; t_c/10: -0.95 %, +2.3 %;
// t_c/5: -2.9 %, +6.3 %. The paper recommends dt <= t_c/50 and runs its Brazil nut at
// t_c/25 (dt = 2e-4, t_c = 4.97e-3 for two small spheres).
#include <string>

#include "contact_parts.hpp"
#include "model.hpp"
#include "particles.hpp"
#include "walls.hpp"

namespace granpipe::dem {

inline constexpr double kWarnAboveContactFraction = 1.0 / 20.0;
inline constexpr double kRefuseAboveContactFraction = 1.0 / 10.0;

struct ContactTime {
  double t_c = 0.0;
  std::string between;  // "species 0 and species 0", "species 1 and wall cylinder"
};

// The shortest contact over the species present in `radius`/`species` and the active
// walls (InputError for a species the model does not have, so that a source can check
// dt before making the engine). For the Hertz law the contact time depends on the impact: it is
// taken at normal speed `impact_speed` (> 0; the fastest approach the scene can produce), undamped.
ContactTime smallest_contact_time(const Model& model, const WallSet& walls,
                                  const Eigen::ArrayXd& radius, const Eigen::ArrayXi& species,
                                  ContactLaw law, double impact_speed);

enum class StepVerdict { Fine, Warn, Refuse };

struct StepCheck {
  StepVerdict verdict;
  std::string message;  // empty when fine; one line naming dt, t_c and the pair
};
StepCheck check_time_step(double dt, const ContactTime& shortest);

}  // namespace granpipe::dem
