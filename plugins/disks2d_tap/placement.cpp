#include "placement.hpp"

#include <algorithm>
#include <cmath>
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
  DiskGrid grid;
  grid.reset(width, height, std::sqrt(2.0) * r_min * (1.0 - 1e-9), 2.0 * r_max);
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const double ri = radii[i];
    bool placed = false;
    for (int attempt = 0; attempt < attempts && !placed; ++attempt) {
      const double x = rng.uniform(ri, width - ri), y = rng.uniform(ri, height - ri);
      bool overlap = false;
      const double reach = ri + r_max;
      grid.for_each_in(x - reach, x + reach, y - reach, y + reach, [&](std::int32_t j) {
        const auto m = static_cast<std::size_t>(j);
        const double dx = packing.x[m] - x, dy = packing.y[m] - y, R = ri + packing.r[m];
        overlap = overlap || dx * dx + dy * dy < R * R;
      });
      if (overlap) continue;
      grid.put(static_cast<std::int32_t>(i), grid.cell_of(x, y));
      packing.add(x, y, ri);
      placed = true;
    }
    if (!placed) {
      std::ostringstream s;
      s << where << ": random placement found no room for disk " << i + 1 << " of "
        << radii.size() << " after " << attempts << " attempts in a box of " << width
        << " x " << height << "; expected fewer or smaller disks or a lower initial fraction";
      throw InputError(s.str());
    }
  }
  return packing;
}

}  // namespace granpipe::disks2d_tap
