#include "placement.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "disk_grid.hpp"
#include "granpipe/errors.hpp"

namespace granpipe::disks2d_tap {

DiskPacking place_at_random(double width, double height, const std::vector<double>& radii,
                            RandomStream& rng, const std::string& where, int attempts) {
  DiskPacking packing;
  packing.width = width;
  if (radii.empty()) return packing;
  const double r_min = *std::min_element(radii.begin(), radii.end());
  const double r_max = *std::max_element(radii.begin(), radii.end());
  if (2.0 * r_max > width || 2.0 * r_max > height) {
    std::ostringstream s;
    s << where << ": expected disks narrower than the box, got diameter " << 2.0 * r_max
      << " in a box of width " << width << " and height " << height;
    throw InputError(s.str());
  }
  // The largest disks go first, while there is room for them (ties keep their index
  // order, so equal disks are placed in index order).
  std::vector<std::size_t> order(radii.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return radii[a] > radii[b]; });
  std::vector<double> xs(radii.size()), ys(radii.size());
  DiskGrid grid;
  grid.reset(width, height, std::sqrt(2.0) * r_min * (1.0 - 1e-9), 2.0 * r_max);
  for (std::size_t placed_count = 0; placed_count < order.size(); ++placed_count) {
    const std::size_t i = order[placed_count];
    const double ri = radii[i];
    bool placed = false;
    for (int attempt = 0; attempt < attempts && !placed; ++attempt) {
      const double x = rng.uniform(ri, width - ri), y = rng.uniform(ri, height - ri);
      bool overlap = false;
      const double reach = ri + r_max;
      grid.for_each_in(x - reach, x + reach, y - reach, y + reach, [&](std::int32_t j) {
        const auto m = static_cast<std::size_t>(j);
        const double dx = xs[m] - x, dy = ys[m] - y, R = ri + radii[m];
        overlap = overlap || dx * dx + dy * dy < R * R;
      });
      if (overlap) continue;
      grid.put(static_cast<std::int32_t>(i), grid.cell_of(x, y));
      xs[i] = x;
      ys[i] = y;
      placed = true;
    }
    if (!placed) {
      std::ostringstream s;
      s << where << ": random placement found no room for disk " << placed_count + 1 << " of "
        << radii.size() << " after " << attempts << " attempts in a box of " << width << " x "
        << height << "; expected fewer or smaller disks or a lower initial fraction";
      throw InputError(s.str());
    }
  }
  for (std::size_t i = 0; i < radii.size(); ++i) packing.add(xs[i], ys[i], radii[i]);
  return packing;
}

}  // namespace granpipe::disks2d_tap
