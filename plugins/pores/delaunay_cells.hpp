#pragma once
// The finite cells of the 3D Delaunay triangulation of a frame's particle centres (CGAL,
// exact predicates): each cell's circumsphere and its height, the smallest distance from
// a vertex to the plane of the other three.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "granpipe/frame.hpp"
#include "periodic_images.hpp"

namespace granpipe::pores {

struct DelaunayCell {
  Eigen::Vector3d centre;                   // of the circumsphere
  double radius = 0.0;                      // of the circumsphere
  double height = 0.0;                      // how far the cell is from flat
  std::array<std::uint32_t, 4> vertices{};  // rows of the Centres triangulated
};

// The cells of `centres` (the frame names their particles). Throws InputError after
// `where` for two particles at one position (naming both) and centres that span no
// volume (all coplanar or collinear).
std::vector<DelaunayCell> delaunay_cells(const Centres& centres, const Frame& frame,
                                         const std::string& where);

}  // namespace granpipe::pores
