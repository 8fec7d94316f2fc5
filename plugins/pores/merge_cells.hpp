#pragma once
// Delaunay cells with one circumsphere are one pore: the triangulation splits a site
// whose neighbours are cospherical (an octahedral site, a cube) into several cells, in an
// order that depends on its tie-breaking. Spheres closer than a tolerance (relative to the
// particle radius) in centre and radius are the same sphere; flat cells are no pores.
#include <Eigen/Core>
#include <vector>

#include "delaunay_cells.hpp"

namespace granpipe::pores {

struct Pore {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // mean of its cells' circumcentres
  double radius = 0.0;  // mean of its cells' circumradii (not yet minus the sphere's)
  int cells = 0;
};

struct MergedPores {
  std::vector<Pore> pores;
  long flat_cells = 0;  // cells thinner than the tolerance, left out
};

// Flat cells (lower than tolerance * radius) are left out: their four centres are in one
// plane at that precision, so that their circumsphere is set by rounding, not by the
// packing. Cells marked no pore are left out too. The others are grouped, transitively,
// when their circumcentres are within tolerance * radius of each other and so are their
// circumradii. Only neighbours are compared, across a face or across a flat cell between
// them: the cells of one empty sphere fill the polyhedron of its cospherical centres, so
// that they are joined by faces, where rounding may leave slivers.
MergedPores merge_cells(const std::vector<DelaunayCell>& cells, double radius, double tolerance,
                        int threads);

}  // namespace granpipe::pores
