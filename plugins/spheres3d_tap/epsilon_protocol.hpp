#pragma once
// The dilation of every tap: constant, or the paper's stepped ramps of sqrt(epsilon)
// (Fig. 4: sqrt(epsilon) raised by a step every M taps from its lowest to its highest
// value, lowered back, raised again: one leg per direction).
#include <cstdint>

namespace granpipe::spheres3d_tap {

struct EpsilonAt {
  double epsilon = 0.0;
  int leg = -1;            // the ramp's leg (0 up, 1 down, 2 up, ...); -1 constant
  bool ends_step = false;  // the last tap at this value (a ramp's measuring point)
};

class EpsilonProtocol {
 public:
  static EpsilonProtocol constant(double epsilon, std::int64_t taps);
  // sqrt(epsilon) from root_min to root_max in steps of root_step (the last step may
  // land below root_max), `taps_per_step` taps each, over `legs` legs.
  static EpsilonProtocol ramp(double root_min, double root_max, double root_step,
                              std::int64_t taps_per_step, int legs);

  // The taps of such a ramp with `steps` steps up a leg, in doubles, for the caller to
  // check against the 64-bit range first: the first leg visits steps + 1 values, each
  // later leg turns at the end and visits steps.
  static double ramp_taps(double steps, double taps_per_step, double legs) {
    return taps_per_step * ((steps + 1) + (legs - 1) * steps);
  }

  std::int64_t taps() const { return taps_; }
  EpsilonAt at(std::int64_t tap) const;  // tap from 1 to taps()

 private:
  double constant_ = 0.0, root_min_ = 0.0, root_step_ = 0.0;
  std::int64_t taps_ = 0, per_step_ = 0, steps_ = 0;  // steps_: values per leg beyond the first
  bool ramped_ = false;
};

}  // namespace granpipe::spheres3d_tap
