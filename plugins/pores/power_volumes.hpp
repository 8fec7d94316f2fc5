#pragma once
// The volume of every point's power (Laguerre) cell, read off the dual triangulation: a
// cell T with orthogonal centre c_T, a face of it, the foot f of c_T on that face's plane
// (where the face's dual edge crosses it) and an edge ab of that face make the tetrahedron
// (x_a, x_b, f, c_T); the radical plane of a and b, which holds f and c_T, splits it into a
// piece of a's cell and a piece of b's, in the ratio of the distances from x_a and x_b to
// that plane. Signed volumes make the sum exact however the centres lie, inside their
// cells or not (as power centres may).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cell_bounds.hpp"

namespace granpipe::pores {

// The points of a power diagram and their weights (squared radii; none: all 0, the
// Voronoi diagram), and the largest weight of any point that could be missing (0: none).
struct WeightedPoints {
  const std::vector<Eigen::Vector3d>& position;
  const std::vector<double>& weights;
  double largest_missing_weight = 0.0;

  double weight(std::uint32_t k) const { return weights.empty() ? 0.0 : weights[k]; }
  // How far from `c` a point could cut the cell of point k that has a vertex at c: the
  // radius of the sphere orthogonal to k's there, grown by the largest missing weight.
  double reach(const Eigen::Vector3d& c, std::uint32_t k) const;
};

struct PowerVolumes {
  std::vector<double> volume;       // per point triangulated
  std::vector<std::uint8_t> flags;  // per point: CellFlag bits
  // Per point: how far the orthogonal sphere of one of its cells sticks out beyond the
  // images along periodic axes, at most (a point outside that sphere could cut the cell).
  std::vector<double> shortfall;
};

// Each point's flags and shortfall from its cells, whatever their order and numbering,
// and the points on the hull (kUnbounded); volumes 0. Cell is DualCell or derived from it.
template <class Cell>
PowerVolumes cell_extents(const WeightedPoints& points, const std::vector<Cell>& cells,
                          const std::vector<std::uint32_t>& hull, const CellBounds& bounds,
                          int threads);

// Adds each point's volume. Each of `threads` sums the cells of its own share of the
// points, in the cells' order: the bits do not depend on the threads.
template <class Cell>
void sum_volumes(PowerVolumes& v, const WeightedPoints& points, const std::vector<Cell>& cells,
                 int threads);

}  // namespace granpipe::pores
