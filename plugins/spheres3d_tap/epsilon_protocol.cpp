#include "epsilon_protocol.hpp"

#include <cmath>

namespace granpipe::spheres3d_tap {

EpsilonProtocol EpsilonProtocol::constant(double epsilon, std::int64_t taps) {
  EpsilonProtocol p;
  p.constant_ = epsilon;
  p.taps_ = taps;
  return p;
}

EpsilonProtocol EpsilonProtocol::ramp(double root_min, double root_max, double root_step,
                                      std::int64_t taps_per_step, int legs) {
  EpsilonProtocol p;
  p.ramped_ = true;
  p.root_min_ = root_min;
  p.root_step_ = root_step;
  p.per_step_ = taps_per_step;
  p.steps_ = static_cast<std::int64_t>(std::floor((root_max - root_min) / root_step + 1e-9));
  p.taps_ = static_cast<std::int64_t>(
      ramp_taps(static_cast<double>(p.steps_), static_cast<double>(taps_per_step), legs));
  return p;
}

EpsilonAt EpsilonProtocol::at(std::int64_t tap) const {
  if (!ramped_) return {constant_, -1, true};
  const std::int64_t step = (tap - 1) / per_step_;  // 0-based over the whole ramp
  const bool ends = tap % per_step_ == 0;
  // Leg 0 holds values 0..steps_; leg l > 0 holds steps_ values, going down for odd l.
  int leg = 0;
  std::int64_t k = step;
  if (step > steps_) {
    const std::int64_t later = step - (steps_ + 1);
    leg = 1 + static_cast<int>(later / steps_);
    const std::int64_t within = later % steps_;
    k = leg % 2 == 1 ? steps_ - 1 - within : 1 + within;
  }
  const double root = root_min_ + static_cast<double>(k) * root_step_;
  return {root * root, leg, ends};
}

}  // namespace granpipe::spheres3d_tap
