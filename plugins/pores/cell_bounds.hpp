#pragma once
// Where the vertices of a particle's power cell may lie for the cell to be the particle's
// in its container. The cell is convex: it lies inside the container when its vertices do.
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "granpipe/frame.hpp"
#include "skin.hpp"

namespace granpipe::pores {

// What a particle's cell is, as bits: the cell of a particle of the frame has none.
enum CellFlag : std::uint8_t {
  kUnbounded = 1,   // a vertex at infinity: a face on the hull of the points triangulated
  kOutside = 2,     // a vertex beyond an open side (the packing's surface) or the cylinder
  kBeyondWall = 4,  // a vertex beyond a plane wall: the cell is to be cut at the wall
  kSeen = 8,        // in some cell (without: hidden in a regular triangulation, no cell)
  // kOutside at a vertex on the inner side of every wall: the cell cut at the walls keeps
  // that vertex, and is outside as well.
  kOutsideWithinWalls = 16,
};

class CellBounds {
 public:
  // A vertex may stray `tolerance` (a length) beyond a wall or the cylinder: rounding puts
  // the vertices of a lattice's cells that lie on a wall a hair either side of it. The
  // images along periodic sides reach `skin` beyond the box.
  CellBounds(const Frame& frame, double tolerance, const Skin& skin);

  // kOutside (with kOutsideWithinWalls), kBeyondWall or both for a vertex at `c`; 0
  // inside.
  std::uint8_t breach(const Eigen::Vector3d& c) const;
  // How far the sphere (c, reach) sticks out of the box along its periodic axes beyond the
  // skin; 0 within it.
  double periodic_shortfall(const Eigen::Vector3d& c, double reach) const;

  bool has_plane_walls() const { return plane_walls_; }
  bool has_periodic_axes() const { return periodic_[0] || periodic_[1] || periodic_[2]; }
  // The box the cells at plane walls are cut from: the walls themselves; beyond an open
  // side's limit or the cylinder (a cell reaching that far is outside), a period beyond
  // the box along periodic axes (the images bound the cells there).
  const std::array<Eigen::Vector3d, 2>& cut_box() const { return cut_box_; }

 private:
  // Per axis and side: the limit (infinite where there is none) and the flag beyond it.
  std::array<std::array<double, 2>, 3> limit_{};
  std::array<std::array<std::uint8_t, 2>, 3> flag_{};
  std::array<bool, 3> periodic_{};
  Eigen::Vector3d box_lo_, box_hi_;
  Skin skin_;
  bool cylinder_ = false;
  Eigen::Vector2d axis_ = Eigen::Vector2d::Zero();  // the cylinder's, moved by the offset
  double cylinder_limit_ = 0.0;                     // its radius plus the tolerance
  bool plane_walls_ = false;
  std::array<Eigen::Vector3d, 2> cut_box_;
};

}  // namespace granpipe::pores
