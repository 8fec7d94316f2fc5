#include "deep_overlap.hpp"

#include <algorithm>
#include <cmath>

#include "granpipe/format_number.hpp"
#include "overlap_limit.hpp"

namespace granpipe::dem {

DeepOverlap deepest_overlap(const Particles& p, const NeighborList& list, const WallSet& walls,
                            const Eigen::Vector3d& offset) {
  DeepOverlap deepest;
  const auto consider = [&](const DeepOverlap& d) {
    if (d.fraction > deepest.fraction) deepest = d;
  };
  for (int i = 0; i < p.size(); ++i) {
    const auto tag = p.tag[static_cast<std::size_t>(i)];
    for (std::int32_t k = list.first[i]; k < list.first[i + 1]; ++k) {
      const int j = list.partner[k];
      const double delta = p.radius[i] + p.radius[j] - (p.x.col(i) - p.x.col(j)).norm();
      const auto [a, b] = std::minmax(tag, p.tag[static_cast<std::size_t>(j)]);
      consider({a, b, Wall::Count, delta / std::min(p.radius[i], p.radius[j])});
    }
    for (int slot = 0; slot < walls.count(); ++slot) {
      Eigen::Vector3d n;
      const double delta = walls.overlap(slot, p.x.col(i), p.radius[i], offset, n);
      consider({tag, -1, walls.wall_of_slot(slot), delta / p.radius[i]});
    }
  }
  return deepest;
}

std::string describe(const DeepOverlap& d) {
  const std::string percent = format_number(100.0 * d.fraction, 3) + " %";
  const std::string limit =
      " (a sound run stays within " + format_number(100.0 * kMaxOverlapFraction) + " %)";
  if (d.other >= 0) {
    return "particles " + std::to_string(d.tag) + " and " + std::to_string(d.other) +
           " overlap by " + percent + " of the smaller radius" + limit;
  }
  return "particle " + std::to_string(d.tag) + " overlaps wall " + to_string(d.wall) + " by " +
         percent + " of its radius" + limit;
}

}  // namespace granpipe::dem
