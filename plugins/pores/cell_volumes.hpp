#pragma once
// The volume of each particle's cell: its Voronoi cell for equal spheres, its Laguerre
// (power) cell, weights r^2, for unequal ones. Periodic sides by the images triangulated,
// plane walls by mirror images of the particles near them; a cell that stays unbounded or
// reaches beyond the packing's open surface or the cylinder is undefined (NaN).
#include <Eigen/Core>
#include <vector>

#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct CellVolumes {
  Eigen::ArrayXd volume;  // per particle; NaN undefined, 0 for a hidden sphere
  long undefined = 0;     // cells unbounded or reaching out of the container
  long hidden = 0;        // unequal radii: spheres whose power cell is empty
  // Along periodic axes: how far beyond the box the images must reach for the defined
  // cells to be those of the periodic packing.
  double skin_needed = 0.0;
};

// Equal spheres: the Voronoi cells, from the triangulation of the pores and its `cells`
// (mirror images are inserted into it when the container has plane walls).
CellVolumes voronoi_volumes(DelaunayTriangulation& t, const std::vector<DelaunayCell>& cells,
                            const Centres& centres, const Frame& frame, double tolerance);

// Unequal spheres: the Laguerre cells, from a regular triangulation of their own.
CellVolumes laguerre_volumes(const Centres& centres, const Frame& frame, double tolerance);

}  // namespace granpipe::pores
