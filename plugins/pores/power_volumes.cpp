#include "power_volumes.hpp"

#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "delaunay_cells.hpp"

namespace granpipe::pores {

namespace {

// For each face (opposite vertex i) of a positively oriented cell, its corners ordered so
// that they and vertex i are positively oriented too; then every pair (a, b) of
// consecutive corners (a, b, c) is positively oriented with i, which orders T and its
// neighbour N around the edge ab.
constexpr std::array<std::array<int, 3>, 4> kFaces{{{2, 1, 3}, {0, 2, 3}, {1, 0, 3}, {0, 1, 2}}};

std::array<std::uint32_t, 3> face(const CellTopology& cell, int i) {
  const auto& v = cell.vertices;
  return {v[kFaces[i][0]], v[kFaces[i][1]], v[kFaces[i][2]]};
}

// What one thread adds up: the points in rows [first, end).
struct Share {
  const WeightedPoints& points;
  PowerVolumes& out;
  std::uint32_t first, end;

  bool owns(std::uint32_t k) const { return k >= first && k < end; }
  bool owns_any(const CellTopology& cell) const {
    const auto& v = cell.vertices;
    return std::any_of(v.begin(), v.end(), [&](std::uint32_t k) { return owns(k); });
  }

  template <class Cell>
  void add_extent(const Cell& cell, const CellBounds& bounds) {
    if (!owns_any(cell)) return;
    const std::uint8_t flags = bounds.breach(cell.centre) | kSeen;
    const double shortfall =
        bounds.has_periodic_axes()
            ? bounds.periodic_shortfall(cell.centre, points.reach(cell.centre, cell.vertices[0]))
            : 0.0;
    for (std::uint32_t k : cell.vertices) {
      if (!owns(k)) continue;
      out.flags[k] |= flags;
      out.shortfall[k] = std::max(out.shortfall[k], shortfall);
    }
  }

  // The wedge of the dual face of ab between c_n and c_t (c_n before c_t around a -> b),
  // as the tetrahedron (x_a, x_b, c_n, c_t) split by the radical plane of a and b.
  void add_wedge(std::uint32_t a, std::uint32_t b, const Eigen::Vector3d& c_n,
                 const Eigen::Vector3d& c_t) {
    if (!owns(a) && !owns(b)) return;
    const std::vector<Eigen::Vector3d>& x = points.position;
    const Eigen::Vector3d ab = x[b] - x[a];
    const double six_volume = ab.dot((c_n - x[a]).cross(c_t - x[a]));
    // The radical plane cuts ab at the fraction t_a from a: the middle without weights
    // (0.5 + 0 / |ab|^2 too, to the bit, but for the division's time).
    const double t_a = points.weights.empty()
                           ? 0.5
                           : 0.5 + (points.weight(a) - points.weight(b)) / (2.0 * ab.squaredNorm());
    if (owns(a)) out.volume[a] += t_a * six_volume / 6.0;
    if (owns(b)) out.volume[b] += (1.0 - t_a) * six_volume / 6.0;
  }

  // The wedges of cell t with its neighbours after it (those before added theirs with it).
  template <class Cell>
  void add_wedges(const Cell& cell, std::size_t t, const std::vector<Eigen::Vector3d>& centre) {
    if (!owns_any(cell)) return;
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t n = cell.neighbours[i];
      if (n == kHull || n < t) continue;
      const std::array<std::uint32_t, 3> f = face(cell, i);
      for (int e = 0; e < 3; ++e) add_wedge(f[e], f[(e + 1) % 3], centre[n], cell.centre);
    }
  }
};

// The neighbours' centres of a cell some cells ahead, fetched into the cache while the
// cells before it are summed: they lie anywhere in the array, and waiting on them was half
// of the sums' time.
constexpr std::size_t kPrefetchAhead = 8;

template <class Cell>
void prefetch_neighbours(const Cell& cell, const std::vector<Eigen::Vector3d>& centre) {
  for (std::uint32_t n : cell.neighbours)
    if (n != kHull) __builtin_prefetch(&centre[n]);
}

// Runs add(share) on each thread, each with its own share of the points.
template <class Add>
void by_shares(const WeightedPoints& points, PowerVolumes& out, int threads, Add add) {
  const std::size_t n = points.position.size();
#pragma omp parallel num_threads(threads)
  {
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const auto parts = static_cast<std::size_t>(omp_get_num_threads());
    Share share{points, out, static_cast<std::uint32_t>(n * part / parts),
                static_cast<std::uint32_t>(n * (part + 1) / parts)};
    add(share);
  }
}

}  // namespace

double WeightedPoints::reach(const Eigen::Vector3d& c, std::uint32_t k) const {
  const double power = (c - position[k]).squaredNorm() - weight(k);
  return std::sqrt(std::max(0.0, power + largest_missing_weight));
}

template <class Cell>
PowerVolumes cell_extents(const WeightedPoints& points, const std::vector<Cell>& cells,
                          const std::vector<std::uint32_t>& hull, const CellBounds& bounds,
                          int threads) {
  const std::size_t n = points.position.size();
  PowerVolumes out{std::vector<double>(n, 0.0), std::vector<std::uint8_t>(n, 0),
                   std::vector<double>(n, 0.0)};
  by_shares(points, out, threads, [&](Share& share) {
    for (const Cell& cell : cells) share.add_extent(cell, bounds);
  });
  for (std::uint32_t k : hull) out.flags[k] |= kUnbounded;
  return out;
}

template <class Cell>
void sum_volumes(PowerVolumes& v, const WeightedPoints& points, const std::vector<Cell>& cells,
                 int threads) {
  // The neighbours' centres from an array a third the size of the cells', more of it in
  // cache.
  std::vector<Eigen::Vector3d> centre(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) centre[t] = cells[t].centre;
  by_shares(points, v, threads, [&](Share& share) {
    for (std::size_t t = 0; t < cells.size(); ++t) {
      if (t + kPrefetchAhead < cells.size()) prefetch_neighbours(cells[t + kPrefetchAhead], centre);
      share.add_wedges(cells[t], t, centre);
    }
  });
}

template PowerVolumes cell_extents<DualCell>(const WeightedPoints&, const std::vector<DualCell>&,
                                             const std::vector<std::uint32_t>&, const CellBounds&,
                                             int);
template PowerVolumes cell_extents<DelaunayCell>(const WeightedPoints&,
                                                 const std::vector<DelaunayCell>&,
                                                 const std::vector<std::uint32_t>&,
                                                 const CellBounds&, int);
template void sum_volumes<DualCell>(PowerVolumes&, const WeightedPoints&,
                                    const std::vector<DualCell>&, int);
template void sum_volumes<DelaunayCell>(PowerVolumes&, const WeightedPoints&,
                                        const std::vector<DelaunayCell>&, int);

}  // namespace granpipe::pores
