#include "tap_schedule.hpp"

#include <cmath>

namespace granpipe::spheres3d_tap {

bool SaveSchedule::saves(std::int64_t tap) const {
  if (tap == 0) return start;
  if (tap % every == 0) return true;
  if (!logarithmic) return false;
  // Tap t is saved when it is the first tap at or past 10^(k/10) for some k: the largest
  // such power not above t lies above t - 1.
  const double t = static_cast<double>(tap);
  const double k = std::floor(10.0 * std::log10(t) + 1e-9);
  return std::pow(10.0, k / 10.0) > t - 1.0;
}

}  // namespace granpipe::spheres3d_tap
