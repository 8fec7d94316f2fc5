#include "merge_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "granpipe/connected_components.hpp"

namespace granpipe::pores {

namespace {

using Key = std::array<std::int64_t, 3>;

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    const auto u = [](std::int64_t x) { return static_cast<std::uint64_t>(x); };
    return static_cast<std::size_t>(u(k[0]) * 73856093u ^ u(k[1]) * 19349663u ^
                                    u(k[2]) * 83492791u);
  }
};

// Circumcentres hashed into cubes of the tolerance's size: a sphere's equals lie in its
// cube or the 26 around it. Far-away centres (nearly flat cells at the hull) are clamped
// to the grid's rim, which only puts more candidates in one cube.
Key key_of(const Eigen::Vector3d& centre, double size) {
  constexpr double rim = 1e18;
  Key k;
  for (int a = 0; a < 3; ++a) {
    k[a] = static_cast<std::int64_t>(std::clamp(std::floor(centre[a] / size), -rim, rim));
  }
  return k;
}

bool same_sphere(const DelaunayCell& a, const DelaunayCell& b, double tolerance) {
  return std::abs(a.radius - b.radius) <= tolerance &&
         (a.centre - b.centre).squaredNorm() <= tolerance * tolerance;
}

std::vector<ParticlePair> same_sphere_pairs(const std::vector<DelaunayCell>& cells,
                                            double tolerance) {
  std::unordered_map<Key, std::vector<std::int64_t>, KeyHash> grid;
  for (std::size_t i = 0; i < cells.size(); ++i)
    grid[key_of(cells[i].centre, tolerance)].push_back(static_cast<std::int64_t>(i));
  std::vector<ParticlePair> pairs;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Key k = key_of(cells[i].centre, tolerance);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dz = -1; dz <= 1; ++dz) {
          const auto found = grid.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (found == grid.end()) continue;
          for (std::int64_t j : found->second) {
            const auto other = static_cast<std::size_t>(j);
            if (other > i && same_sphere(cells[i], cells[other], tolerance))
              pairs.emplace_back(static_cast<std::int64_t>(i), j);
          }
        }
  }
  return pairs;
}

}  // namespace

MergedPores merge_cells(const std::vector<DelaunayCell>& cells, double radius, double tolerance) {
  const double length = tolerance * radius;
  MergedPores merged;
  std::vector<DelaunayCell> solid;
  solid.reserve(cells.size());
  for (const DelaunayCell& c : cells) {
    if (c.height < length) {
      ++merged.flat_cells;
    } else {
      solid.push_back(c);
    }
  }
  const std::vector<ParticlePair> pairs = same_sphere_pairs(solid, length);
  const ConnectedComponents groups =
      connected_components(static_cast<Eigen::Index>(solid.size()), pairs);
  // Groups first (labels 0, 1, ...), then every cell that shares its sphere with none.
  merged.pores.resize(groups.size.size());
  for (std::size_t i = 0; i < solid.size(); ++i) {
    const std::int64_t label = groups.label[static_cast<Eigen::Index>(i)];
    Pore& pore =
        label >= 0 ? merged.pores[static_cast<std::size_t>(label)] : merged.pores.emplace_back();
    pore.centre += solid[i].centre;
    pore.radius += solid[i].radius;
    ++pore.cells;
  }
  for (Pore& p : merged.pores) {
    p.centre /= p.cells;
    p.radius /= p.cells;
  }
  return merged;
}

}  // namespace granpipe::pores
