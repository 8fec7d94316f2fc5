#pragma once
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace granpipe {

// What lies at one side of the box along one axis.
enum class Boundary : std::uint8_t { Wall, Periodic, Open };

enum class ContainerShape : std::uint8_t { Box, Cylinder };

// Walls are numbered so that contacts and support labels can name them.
enum class Wall : std::uint8_t { XLow = 0, XHigh, YLow, YHigh, ZLow, ZHigh, CylinderSide, Count };

const char* to_string(Boundary b);
const char* to_string(ContainerShape s);
const char* to_string(Wall w);

// The vessel the particles are in, at one frame. Gravity points along -axis (dim-1):
// -y in 2D, -z in 3D, so the flat base is the low wall of that axis.
struct Container {
  ContainerShape shape = ContainerShape::Box;
  // Box extents per axis (only the first dim entries are meaningful).
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Ones();
  // boundary[axis][0] is the low side, [1] the high side.
  std::array<std::array<Boundary, 2>, 3> boundary{{{Boundary::Wall, Boundary::Wall},
                                                   {Boundary::Wall, Boundary::Wall},
                                                   {Boundary::Wall, Boundary::Wall}}};
  // Vertical cylinder (3D only): axis along z through (center_x, center_y).
  double cylinder_radius = 0.0;
  Eigen::Vector2d cylinder_center = Eigen::Vector2d::Zero();
  // Moving walls (a vibrated base and cylinder) are displaced together by this offset
  // from their rest geometry above, and move with this velocity, at this frame.
  Eigen::Vector3d wall_offset = Eigen::Vector3d::Zero();
  Eigen::Vector3d wall_velocity = Eigen::Vector3d::Zero();

  bool periodic(int axis) const { return boundary[axis][0] == Boundary::Periodic; }
  // Where the low (side 0) or high (side 1) end of `axis` is at this frame: a wall's rest
  // place displaced by wall_offset (a periodic side does not move).
  double wall_at(int axis, int side) const {
    const double rest = side == 0 ? lo[axis] : hi[axis];
    return periodic(axis) ? rest : rest + wall_offset[axis];
  }
  double length(int axis) const { return hi[axis] - lo[axis]; }
  // A separation along `axis` by the minimum-image convention (unchanged on other axes).
  double minimum_image(int axis, double d) const {
    return periodic(axis) ? d - length(axis) * std::round(d / length(axis)) : d;
  }
  // A coordinate brought back into [lo, hi) along a periodic axis (unchanged on others).
  double wrap(int axis, double x) const {
    if (!periodic(axis)) return x;
    x -= length(axis) * std::floor((x - lo[axis]) / length(axis));
    // Rounding can leave x a hair below lo (the quotient of a tiny offset rounds to -0)
    // or exactly on hi; both belong at lo's side of the box.
    if (x < lo[axis]) x += length(axis);
    return x >= hi[axis] ? lo[axis] : x;
  }

  // A fully periodic box of the given extents.
  static Container periodic_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  // A box with solid walls on every side but an open top.
  static Container open_top_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
};

}  // namespace granpipe
