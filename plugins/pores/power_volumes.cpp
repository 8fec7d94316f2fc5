#include "power_volumes.hpp"

#include <omp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "delaunay_cells.hpp"
#include "granpipe/parallel_errors.hpp"

namespace granpipe::pores {

namespace {

// A cell's corners relative to its centre, x_b x x_a of its edges (a < b) and the
// fraction of each edge ab on a's side of the radical plane of a and b.
struct CellFrame {
  std::array<Eigen::Vector3d, 4> x;
  std::array<std::array<Eigen::Vector3d, 4>, 4> cross;
  std::array<std::array<double, 4>, 4> fraction;

  template <int A, int B>
  Eigen::Vector3d edge_cross() const {
    if constexpr (A < B) {
      return cross[A][B];
    } else {
      return -cross[B][A];
    }
  }
  template <int A, int B>
  double edge_fraction() const {
    if constexpr (A < B) {
      return fraction[A][B];
    } else {
      return 1.0 - fraction[B][A];
    }
  }

  // Adds six times the corners' shares of the cell's part of the dual faces of the edges
  // of face (p, q, r). The face's dual edge crosses its plane at the foot f of the centre,
  // which splits the dual face of each edge ab between this cell and the neighbour across
  // the face; this cell's part is the tetrahedron (x_a, x_b, f, c) (f before c around
  // a -> b when (p, q, r) and the fourth corner are positively oriented), of six times
  // the volume f . (x_b x x_a) with c at the origin, split by the radical plane of a and b.
  template <int P, int Q, int R>
  void add_face(std::array<double, 4>& six_volume) const {
    const Eigen::Vector3d pq = edge_cross<P, Q>(), qr = edge_cross<Q, R>(), rp = edge_cross<R, P>();
    const Eigen::Vector3d normal = -(pq + qr + rp);               // (x_q - x_p) x (x_r - x_p)
    const double foot = x[P].dot(normal) / normal.squaredNorm();  // f = foot * normal
    add_wedge<P, Q>(foot * normal.dot(pq), six_volume);
    add_wedge<Q, R>(foot * normal.dot(qr), six_volume);
    add_wedge<R, P>(foot * normal.dot(rp), six_volume);
  }
  template <int A, int B>
  void add_wedge(double wedge, std::array<double, 4>& six_volume) const {
    const double t_a = edge_fraction<A, B>();
    six_volume[A] += t_a * wedge;
    six_volume[B] += (1.0 - t_a) * wedge;
  }
};

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

  // The cell's share of its corners' cells (CellFrame::add_face), from its own corners and
  // centre only: the neighbour's centre (the tetrahedron (x_a, x_b, c_n, c) before) lies
  // anywhere in memory, and waiting on it was half of the sums' time.
  template <class Cell>
  void add_cell(const Cell& cell) {
    if (!owns_any(cell)) return;
    const auto& v = cell.vertices;
    CellFrame f;
    for (int k = 0; k < 4; ++k) f.x[k] = points.position[v[k]] - cell.centre;
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        f.cross[a][b] = f.x[b].cross(f.x[a]);
        // The middle without weights (0.5 + 0 / |ab|^2 too, to the bit, but for the
        // division's time).
        f.fraction[a][b] = points.weights.empty()
                               ? 0.5
                               : 0.5 + (points.weight(v[a]) - points.weight(v[b])) /
                                           (2.0 * (f.x[b] - f.x[a]).squaredNorm());
      }
    }
    // The faces opposite corners 0 to 3, each ordered so that it and the corner opposite
    // are positively oriented.
    std::array<double, 4> six_volume{};
    f.add_face<2, 1, 3>(six_volume);
    f.add_face<0, 2, 3>(six_volume);
    f.add_face<1, 0, 3>(six_volume);
    f.add_face<0, 1, 2>(six_volume);
    for (int k = 0; k < 4; ++k)
      if (owns(v[k])) out.volume[v[k]] += six_volume[k] / 6.0;
  }
};

// Runs add(share) on each thread, each with its own share of the points.
template <class Add>
void by_shares(const WeightedPoints& points, PowerVolumes& out, int threads, Add add) {
  const std::size_t n = points.position.size();
  ParallelErrors errors;
#pragma omp parallel num_threads(threads)
  errors.run([&] {
    const auto part = static_cast<std::size_t>(omp_get_thread_num());
    const auto parts = static_cast<std::size_t>(omp_get_num_threads());
    Share share{points, out, static_cast<std::uint32_t>(n * part / parts),
                static_cast<std::uint32_t>(n * (part + 1) / parts)};
    add(share);
  });
  errors.rethrow();
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
  by_shares(points, v, threads, [&](Share& share) {
    for (const Cell& cell : cells) share.add_cell(cell);
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
