#pragma once
// The volume of each particle's cell: its Voronoi cell for equal spheres, its Laguerre
// (power) cell, weights r^2, for unequal ones. Periodic sides by the images triangulated,
// plane walls by cutting the cells there at the walls (wall_cells); a cell that stays
// unbounded or reaches beyond the packing's open surface or the cylinder is undefined (NaN).
#include <Eigen/Core>
#include <vector>

#include "cell_bounds.hpp"
#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"
#include "power_volumes.hpp"

namespace granpipe::pores {

struct CellVolumes {
  Eigen::ArrayXd volume;  // per particle; NaN undefined, 0 for a hidden sphere
  long undefined = 0;     // cells unbounded or reaching out of the container
  long hidden = 0;        // unequal radii: spheres whose power cell is empty
  // Along periodic axes: how much farther the images must reach for the defined cells to
  // be those of the periodic packing.
  double shortfall = 0.0;
};

// Equal spheres: the extents (flags, shortfall) of the Voronoi cells, from the Delaunay
// cells in any order and the points on the hull.
PowerVolumes voronoi_extents(const std::vector<DelaunayCell>& cells,
                             const std::vector<std::uint32_t>& hull, const Centres& centres,
                             const CellBounds& bounds, int threads);

// How much farther the images must reach for the particles' cells, as far as the extents
// tell: the cells to be cut at the walls are left out.
double shortfall_of_cells(const PowerVolumes& extents, const Centres& centres);

// Equal spheres: the Voronoi cells, from the Delaunay cells and their extents.
CellVolumes voronoi_volumes(PowerVolumes extents, const std::vector<DelaunayCell>& cells,
                            const Centres& centres, const CellBounds& bounds, int threads);

// Unequal spheres: the Laguerre cells, from a regular triangulation of their own.
CellVolumes laguerre_volumes(const Centres& centres, const Frame& frame, const CellBounds& bounds,
                             int threads);

}  // namespace granpipe::pores
