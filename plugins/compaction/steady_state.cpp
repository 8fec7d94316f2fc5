#include "steady_state.hpp"

#include <cmath>

namespace granpipe::compaction {

SteadyState steady_state(const std::vector<double>& values) {
  SteadyState s;
  double sum = 0.0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    sum += v;
    ++s.frames;
  }
  if (s.frames == 0) {
    s.mean = s.mean_error = s.sigma = std::nan("");
    return s;
  }
  const auto n = static_cast<double>(s.frames);
  s.mean = sum / n;
  double squares = 0.0;
  for (double v : values) {
    if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
  }
  // One frame shows no fluctuation to measure: undefined, not 0.
  s.sigma = s.frames > 1 ? std::sqrt(squares / n) : std::nan("");
  s.mean_error = s.frames > 1 ? s.sigma / std::sqrt(n - 1.0) : std::nan("");
  return s;
}

}  // namespace granpipe::compaction
