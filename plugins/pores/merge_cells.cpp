#include "merge_cells.hpp"

#include <cmath>
#include <cstdint>

#include "granpipe/connected_components.hpp"

namespace granpipe::pores {

namespace {

bool same_sphere(const DelaunayCell& a, const DelaunayCell& b, double tolerance) {
  return std::abs(a.radius - b.radius) <= tolerance &&
         (a.centre - b.centre).squaredNorm() <= tolerance * tolerance;
}

struct SameSphere {
  const std::vector<DelaunayCell>& cells;
  double length;
  std::vector<ParticlePair> pairs;

  bool flat(std::uint32_t i) const { return cells[i].height < length; }
  bool pore(std::uint32_t i) const { return i != kHull && cells[i].pore && !flat(i); }
  void compare(std::uint32_t i, std::uint32_t j) {
    if (pore(i) && pore(j) && same_sphere(cells[i], cells[j], length))
      pairs.emplace_back(std::int64_t{i}, std::int64_t{j});
  }
};

}  // namespace

MergedPores merge_cells(const std::vector<DelaunayCell>& cells, double radius, double tolerance) {
  SameSphere same{cells, tolerance * radius, {}};
  MergedPores merged;
  for (std::uint32_t i = 0; i < cells.size(); ++i) {
    const auto& n = cells[i].neighbours;
    if (!same.flat(i)) {
      for (std::uint32_t j : n)
        if (j != kHull && j > i) same.compare(i, j);
      continue;
    }
    ++merged.flat_cells;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) same.compare(n[a], n[b]);
  }
  const ConnectedComponents groups =
      connected_components(static_cast<Eigen::Index>(cells.size()), same.pairs);
  // Groups first (labels 0, 1, ...), then every cell that shares its sphere with none.
  merged.pores.resize(groups.size.size());
  for (std::uint32_t i = 0; i < cells.size(); ++i) {
    if (!same.pore(i)) continue;
    const std::int64_t label = groups.label[i];
    Pore& pore =
        label >= 0 ? merged.pores[static_cast<std::size_t>(label)] : merged.pores.emplace_back();
    pore.centre += cells[i].centre;
    pore.radius += cells[i].radius;
    ++pore.cells;
  }
  for (Pore& p : merged.pores) {
    p.centre /= p.cells;
    p.radius /= p.cells;
  }
  return merged;
}

}  // namespace granpipe::pores
