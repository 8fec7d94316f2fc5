#pragma once
// A finite cell of a 3D Delaunay or regular triangulation as the volume and pore code
// read it: its corners, its neighbours and the centre of its orthogonal sphere, which is a
// vertex of the dual Voronoi (power) diagram.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>

namespace granpipe::pores {

// A neighbour across a face of the convex hull: the infinite cell.
constexpr std::uint32_t kHull = std::numeric_limits<std::uint32_t>::max();

struct CellTopology {
  std::array<std::uint32_t, 4> vertices{};  // rows of the points triangulated, positively oriented
  std::array<std::uint32_t, 4> neighbours{};  // across the face opposite each vertex; kHull
};

struct DualCell : CellTopology {
  // Circumcentre (Delaunay) or power centre (regular: equal power |c - x|^2 - w to its four).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

}  // namespace granpipe::pores
