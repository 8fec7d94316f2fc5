#include "power_volumes.hpp"

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

struct Accumulator {
  const std::vector<Eigen::Vector3d>& x;
  const std::vector<double>& w;
  PowerVolumes& out;

  double weight(std::uint32_t k) const { return w.empty() ? 0.0 : w[k]; }

  // The wedge of the dual face of ab between c_n and c_t (c_n before c_t around a -> b),
  // as the tetrahedron (x_a, x_b, c_n, c_t) split by the radical plane of a and b.
  void add_wedge(std::uint32_t a, std::uint32_t b, const Eigen::Vector3d& c_n,
                 const Eigen::Vector3d& c_t) {
    const Eigen::Vector3d ab = x[b] - x[a];
    const double six_volume = ab.dot((c_n - x[a]).cross(c_t - x[a]));
    // The radical plane cuts ab at the fraction t_a from a.
    const double t_a = 0.5 + (weight(a) - weight(b)) / (2.0 * ab.squaredNorm());
    out.volume[a] += t_a * six_volume / 6.0;
    out.volume[b] += (1.0 - t_a) * six_volume / 6.0;
  }
};

}  // namespace

template <class Cell>
PowerVolumes power_volumes(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<double>& weights, double largest_weight,
                           const std::vector<Cell>& cells, const CellBounds& bounds) {
  PowerVolumes out{std::vector<double>(points.size(), 0.0),
                   std::vector<std::uint8_t>(points.size(), 0),
                   std::vector<double>(points.size(), 0.0)};
  Accumulator sum{points, weights, out};
  // The neighbours' centres are read in no spatial order: from an array a third the size
  // of the cells', more of it in cache.
  std::vector<Eigen::Vector3d> centre(cells.size());
  for (std::size_t t = 0; t < cells.size(); ++t) centre[t] = cells[t].centre;
  for (std::size_t t = 0; t < cells.size(); ++t) {
    const Cell& cell = cells[t];
    const std::uint32_t v0 = cell.vertices[0];
    const double power = (cell.centre - points[v0]).squaredNorm() - sum.weight(v0);
    const double reach = std::sqrt(std::max(0.0, power + largest_weight));
    const std::uint8_t flags = bounds.breach(cell.centre) | kSeen;
    const double overshoot = bounds.periodic_overshoot(cell.centre, reach);
    for (std::uint32_t v : cell.vertices) {
      out.flags[v] |= flags;
      out.overshoot[v] = std::max(out.overshoot[v], overshoot);
    }
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t n = cell.neighbours[i];
      const std::array<std::uint32_t, 3> face{
          cell.vertices[kFaces[i][0]], cell.vertices[kFaces[i][1]], cell.vertices[kFaces[i][2]]};
      if (n == kHull) {
        for (std::uint32_t v : face) out.flags[v] |= kUnbounded;
        continue;
      }
      if (n < t) continue;  // the pair was added from n
      for (int e = 0; e < 3; ++e) sum.add_wedge(face[e], face[(e + 1) % 3], centre[n], cell.centre);
    }
  }
  return out;
}

template PowerVolumes power_volumes<DualCell>(const std::vector<Eigen::Vector3d>&,
                                              const std::vector<double>&, double,
                                              const std::vector<DualCell>&, const CellBounds&);
template PowerVolumes power_volumes<DelaunayCell>(const std::vector<Eigen::Vector3d>&,
                                                  const std::vector<double>&, double,
                                                  const std::vector<DelaunayCell>&,
                                                  const CellBounds&);

}  // namespace granpipe::pores
