#include "ageing.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::compaction {

Ageing ageing(const std::vector<double>& taps, const std::vector<double>& z_mean,
              const std::vector<std::int64_t>& waiting_times) {
  Ageing a;
  for (const std::int64_t t_w : waiting_times) {
    const auto w = static_cast<double>(t_w);
    const auto at = std::lower_bound(taps.begin(), taps.end(), w);
    if (at == taps.end() || *at != w) {
      a.left_out.push_back(t_w);
      continue;
    }
    const auto start = static_cast<std::size_t>(at - taps.begin());
    for (std::size_t k = start + 1; k < taps.size(); ++k) {
      const double d = z_mean[start] - z_mean[k];
      a.points.push_back({w, taps[k] - w, d * d});
    }
  }
  return a;
}

}  // namespace granpipe::compaction
