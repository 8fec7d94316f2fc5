#pragma once
// The volume of every point's power (Laguerre) cell, read off the dual triangulation: two
// cells T and N sharing a face, and an edge ab of that face, make the tetrahedron
// (x_a, x_b, c_T, c_N) of the centres of the two and of the orthogonal spheres of the
// cells; the radical plane of a and b, which holds c_T and c_N, splits it into a piece of
// a's cell and a piece of b's, in the ratio of the distances from x_a and x_b to that
// plane. Signed volumes make the sum exact however the centres lie, inside their cells or
// not (as power centres may).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "cell_bounds.hpp"

namespace granpipe::pores {

struct PowerVolumes {
  std::vector<double> volume;       // per point triangulated
  std::vector<std::uint8_t> flags;  // per point: CellFlag bits
  // Per point: how far the orthogonal sphere of one of its cells sticks out of the box
  // along periodic axes, at most (a point outside that sphere could cut the cell).
  std::vector<double> overshoot;
};

// `weights`: one per point (squared radii), or empty for an unweighted (Delaunay)
// triangulation; `largest_weight` the largest weight of any point that could be missing
// (0 for none). Cell is DualCell or a type derived from it.
template <class Cell>
PowerVolumes power_volumes(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<double>& weights, double largest_weight,
                           const std::vector<Cell>& cells, const CellBounds& bounds);

}  // namespace granpipe::pores
