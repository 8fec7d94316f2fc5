#include "tap_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::disks2d_tap {

TapSchedule TapSchedule::constant(double A, std::int64_t equilibration, std::int64_t production,
                                  std::int64_t save_every) {
  TapSchedule s;
  s.A_ = A;
  s.equilibration_ = equilibration;
  s.save_every_ = save_every;
  s.total_ = equilibration + production;
  return s;
}

TapSchedule TapSchedule::cooled_constant(double from, double step, std::int64_t taps_per_step,
                                         double A, std::int64_t equilibration,
                                         std::int64_t production, std::int64_t save_every) {
  TapSchedule s = constant(A, equilibration, production, save_every);
  s.cool_from_ = from;
  s.cool_step_ = step;
  s.taps_per_step_ = taps_per_step;
  s.cooling_taps_ = static_cast<std::int64_t>(cooling_levels(from, step, A)) * taps_per_step;
  s.total_ += s.cooling_taps_;
  return s;
}

double TapSchedule::cooling_levels(double from, double step, double A) {
  // Levels from - k step, k = 0, 1, ..., while above A (a hair of rounding tolerated, so
  // that A itself, reached in whole steps, is not a cooling level).
  return std::max(std::ceil((from - A) / step - 1e-9), 0.0);
}

TapSchedule TapSchedule::annealed(double A_min, double A_max, std::int64_t steps,
                                  std::int64_t taps_per_step, std::int64_t cycles,
                                  std::int64_t save_every) {
  TapSchedule s;
  s.annealed_ = true;
  s.A_min_ = A_min;
  s.A_max_ = A_max;
  s.steps_ = steps;
  s.taps_per_step_ = taps_per_step;
  s.save_every_ = save_every;
  s.total_ = static_cast<std::int64_t>(annealed_taps(
      static_cast<double>(steps), static_cast<double>(taps_per_step), static_cast<double>(cycles)));
  return s;
}

TapStep TapSchedule::at(std::int64_t tap) const {
  TapStep step;
  if (!annealed_) {
    if (tap <= cooling_taps_) {
      step.amplitude = cool_from_ - cool_step_ * static_cast<double>((tap - 1) / taps_per_step_);
      return step;
    }
    const std::int64_t t = tap - cooling_taps_;
    step.amplitude = A_;
    step.save = t > equilibration_ && (t - equilibration_) % save_every_ == 0;
    return step;
  }
  const std::int64_t half_length = steps_ * taps_per_step_;
  const std::int64_t q = tap - 1;
  step.cycle = q / half_length;
  const std::int64_t within = q % half_length;
  const std::int64_t k = within / taps_per_step_ + 1;  // 1..steps
  // Both ramps visit the levels A_min + (A_max - A_min) j / steps, j = 0..steps, computed
  // from j alone, so that a level is the same double on the way up and on the way down
  // (A_min + k dA and A_max - k dA differ in the last bit: 1.7000000000000002 and 1.7),
  // and tables keyed by A line the two branches up. The ends are exact.
  const bool rising = step.cycle % 2 == 0;
  const std::int64_t level = rising ? k : steps_ - k;
  if (level == steps_) {
    step.amplitude = A_max_;
  } else if (level == 0) {
    step.amplitude = A_min_;
  } else {
    step.amplitude =
        A_min_ + (A_max_ - A_min_) * static_cast<double>(level) / static_cast<double>(steps_);
  }
  step.save = (within % taps_per_step_ + 1) % save_every_ == 0;
  return step;
}

}  // namespace granpipe::disks2d_tap
