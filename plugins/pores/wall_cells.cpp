#include "wall_cells.hpp"

#include <algorithm>
#include <utility>

#include "convex_cell.hpp"
#include "delaunay_cells.hpp"
#include "granpipe/parallel_errors.hpp"

namespace granpipe::pores {

namespace {

// The other ends of the edges of each point of `rows`, nearest first (the cuts that remove
// the most come first): those of rows[i] are list[start[i]] ... list[start[i + 1] - 1].
struct RowNeighbours {
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> list;
};

template <class Cell>
RowNeighbours neighbours_of(const std::vector<std::uint32_t>& rows, const WeightedPoints& points,
                            const std::vector<Cell>& cells) {
  constexpr std::size_t kNone = ~std::size_t{0};
  std::vector<std::size_t> place(points.position.size(), kNone);
  for (std::size_t i = 0; i < rows.size(); ++i) place[rows[i]] = i;
  // Each edge once from every cell around it, then the repeats dropped.
  RowNeighbours n{std::vector<std::size_t>(rows.size() + 1, 0), {}};
  for (const Cell& cell : cells)
    for (std::uint32_t v : cell.vertices)
      if (place[v] != kNone) n.start[place[v] + 1] += 3;
  for (std::size_t i = 0; i < rows.size(); ++i) n.start[i + 1] += n.start[i];
  n.list.resize(n.start.back());
  std::vector<std::size_t> next(n.start.begin(), n.start.end() - 1);
  for (const Cell& cell : cells) {
    for (std::uint32_t v : cell.vertices) {
      if (place[v] == kNone) continue;
      for (std::uint32_t w : cell.vertices)
        if (w != v) n.list[next[place[v]]++] = w;
    }
  }
  const std::vector<Eigen::Vector3d>& x = points.position;
  std::size_t kept = 0;
  std::vector<std::pair<double, std::uint32_t>> by_distance;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto first = n.list.begin() + static_cast<std::ptrdiff_t>(n.start[i]);
    const auto end = n.list.begin() + static_cast<std::ptrdiff_t>(n.start[i + 1]);
    std::sort(first, end);
    by_distance.clear();
    for (auto w = first, distinct_end = std::unique(first, end); w != distinct_end; ++w)
      by_distance.emplace_back((x[*w] - x[rows[i]]).squaredNorm(), *w);
    std::sort(by_distance.begin(), by_distance.end());
    n.start[i] = kept;
    for (const auto& [distance, w] : by_distance) n.list[kept++] = w;
  }
  n.start.back() = kept;
  n.list.resize(kept);
  return n;
}

// The cell of rows[i] = k, relative to its centre (which keeps the planes' offsets exact to
// rounding of the distances, not of the coordinates).
void cut_cell(ConvexCell& cell, std::size_t i, std::uint32_t k, const RowNeighbours& neighbours,
              const WeightedPoints& points, const CellBounds& bounds) {
  const Eigen::Vector3d& p = points.position[k];
  cell.reset(bounds.cut_box()[0] - p, bounds.cut_box()[1] - p);
  for (std::size_t j = neighbours.start[i]; j < neighbours.start[i + 1] && !cell.empty(); ++j) {
    const std::uint32_t n = neighbours.list[j];
    const Eigen::Vector3d d = points.position[n] - p;
    cell.cut(d, (d.squaredNorm() + points.weight(k) - points.weight(n)) / 2.0);
  }
}

// Sets point k's volume, flags and shortfall from its cell.
void measure_cell(PowerVolumes& v, std::uint32_t k, const ConvexCell& cell,
                  const WeightedPoints& points, const CellBounds& bounds) {
  const Eigen::Vector3d& p = points.position[k];
  v.volume[k] = cell.volume();
  v.flags[k] = cell.empty() ? 0 : kSeen;
  v.shortfall[k] = 0.0;
  for (const Eigen::Vector3d& corner : cell.corners()) {
    v.flags[k] |= bounds.breach(corner + p);
    if (bounds.has_periodic_axes()) {
      v.shortfall[k] = std::max(v.shortfall[k],
                                bounds.periodic_shortfall(corner + p, points.reach(corner + p, k)));
    }
  }
}

}  // namespace

template <class Cell>
void cut_at_walls(PowerVolumes& v, const std::vector<std::uint32_t>& rows,
                  const WeightedPoints& points, const std::vector<Cell>& cells,
                  const CellBounds& bounds, int threads) {
  const RowNeighbours neighbours = neighbours_of(rows, points, cells);
  const auto n = static_cast<std::ptrdiff_t>(rows.size());
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  {
    ConvexCell cell;
#pragma omp for schedule(dynamic, 16)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
      errors.run([&] {
        cut_cell(cell, static_cast<std::size_t>(i), rows[i], neighbours, points, bounds);
        measure_cell(v, rows[i], cell, points, bounds);
      });
    }
  }
  errors.rethrow();
}

template void cut_at_walls<DualCell>(PowerVolumes&, const std::vector<std::uint32_t>&,
                                     const WeightedPoints&, const std::vector<DualCell>&,
                                     const CellBounds&, int);
template void cut_at_walls<DelaunayCell>(PowerVolumes&, const std::vector<std::uint32_t>&,
                                         const WeightedPoints&, const std::vector<DelaunayCell>&,
                                         const CellBounds&, int);

}  // namespace granpipe::pores
