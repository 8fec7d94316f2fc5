#pragma once
// For spheres of unequal radii the Delaunay cells of the centres are the candidate pores,
// and each cell's sphere is the one tangent to its four particles (tangent_sphere), not
// its circumsphere.
#include <Eigen/Core>
#include <vector>

#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct TangentCells {
  // Centre: the tangent sphere's. Radius: its radius plus the mean particle radius R, so
  // that, as for equal spheres' circumspheres, radius / R - 1 is xi and the merge and the
  // periodic skin treat both alike.
  std::vector<DelaunayCell> cells;
  // The circumcentres of the cells whose four spheres no sphere touches from outside, left
  // out: where they are tells the primary cell's from those at the hull of the images.
  std::vector<Eigen::Vector3d> untangent;
};

// Cells lower than flat_height are kept as they are, for merge_cells to count as flat.
TangentCells tangent_cells(const std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, double flat_height);

}  // namespace granpipe::pores
