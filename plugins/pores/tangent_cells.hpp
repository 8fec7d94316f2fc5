#pragma once
// For spheres of unequal radii the Delaunay cells of the centres are the candidate pores,
// and each cell's sphere is the one tangent to its four particles (tangent_sphere), not
// its circumsphere.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "delaunay_cells.hpp"
#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

// The cells left out, by their circumcentres (where they are tells the primary cell's
// from those at the hull of the images).
struct NonPoreCells {
  std::vector<Eigen::Vector3d> untangent;       // no sphere touches their four from outside
  std::vector<Eigen::Vector3d> fifth_sphere;    // their tangent sphere overlaps a fifth sphere
  std::vector<std::size_t> fifth_sphere_cells;  // those cells, by index
};

// Each cell's centre becomes its tangent sphere's, its radius that sphere's radius plus
// the mean particle radius R, so that, as for equal spheres' circumspheres, radius / R - 1
// is xi and the merge and the periodic skin treat both alike. Flat cells are kept as they
// are, for merge_cells to count. A cell without a tangent sphere, or whose tangent sphere
// overlaps a fifth sphere by more than `length`, is no pore: it is no vertex of the
// spheres' additively weighted Voronoi diagram. Every sphere is asked for the tangent
// spheres centred where `may_count` holds (in the region, once along periodic sides); for
// the others (the hull above a free surface or of the images), the spheres next to the
// four in the triangulation and those more than twice the mean radius wide.
using MayCount = std::function<bool(const Eigen::Vector3d&)>;
NonPoreCells tangent_cells(std::vector<DelaunayCell>& cells, const Centres& centres,
                           const Frame& frame, double mean_radius, const MayCount& may_count,
                           double length, int threads);

}  // namespace granpipe::pores
