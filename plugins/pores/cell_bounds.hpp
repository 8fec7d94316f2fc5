#pragma once
// Where the vertices of a particle's power cell may lie for the cell to be the particle's
// in its container. The cell is convex: it lies inside the container when its vertices do.
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "granpipe/frame.hpp"

namespace granpipe::pores {

// What a particle's cell is, as bits: the cell of a particle of the frame has none.
enum CellFlag : std::uint8_t {
  kUnbounded = 1,   // a vertex at infinity: a face on the hull of the points triangulated
  kOutside = 2,     // a vertex beyond an open side (the packing's surface) or the cylinder
  kBeyondWall = 4,  // a vertex beyond a plane wall: mirror images missing
  kSeen = 8,        // in some cell (without: hidden in a regular triangulation, no cell)
};

class CellBounds {
 public:
  // A vertex may stray `tolerance` (a length) beyond a wall or the cylinder: rounding puts
  // the vertices of a lattice's cells that lie on a wall a hair either side of it.
  CellBounds(const Frame& frame, double tolerance);

  // kOutside, kBeyondWall or both for a vertex at `c`; 0 inside.
  std::uint8_t breach(const Eigen::Vector3d& c) const;
  // How far the sphere (c, reach) sticks out of the box along its periodic axes; 0 inside.
  double periodic_overshoot(const Eigen::Vector3d& c, double reach) const;

 private:
  // Per axis and side: the limit (infinite where there is none) and the flag beyond it.
  std::array<std::array<double, 2>, 3> limit_{};
  std::array<std::array<std::uint8_t, 2>, 3> flag_{};
  std::array<bool, 3> periodic_{};
  Eigen::Vector3d box_lo_, box_hi_;
  bool cylinder_ = false;
  Eigen::Vector2d axis_ = Eigen::Vector2d::Zero();  // the cylinder's, moved by the offset
  double cylinder_limit_ = 0.0;                     // its radius plus the tolerance
};

}  // namespace granpipe::pores
