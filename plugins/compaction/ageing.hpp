#pragma once
// The squared differences of <Z> behind the ageing function of Eq. (5),
//   A(t, t_w) = mean over realizations of (<Z>(t_w) - <Z>(t_w + t))^2,
// for one realization (one run): the mean over realizations is taken across the sweep
// points of the `replica` parameter (scripts/pool_ageing.py). t_w is the age of the
// packing at the first configuration, t the taps elapsed since; so A(0, t_w) = 0 and A
// grows with t to A_inf, as Eq. (6) has it, more slowly for older packings.
#include <cstdint>
#include <vector>

namespace granpipe::compaction {

struct AgeingPoint {
  double t_w = 0.0, t = 0.0, squared_difference = 0.0;
};

struct Ageing {
  std::vector<AgeingPoint> points;     // by t_w as given, then t increasing
  std::vector<std::int64_t> left_out;  // waiting times that are no frame's tap
};

// `taps` increasing, `z_mean` their <Z>: every frame after each t_w that is a frame's tap.
Ageing ageing(const std::vector<double>& taps, const std::vector<double>& z_mean,
              const std::vector<std::int64_t>& waiting_times);

}  // namespace granpipe::compaction
