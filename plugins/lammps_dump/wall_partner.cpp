#include "wall_partner.hpp"

#include <cmath>

namespace granpipe::lammps_dump {

namespace {

// Calls offer(wall, normal, distance of `point` from it) for each solid wall of `c`.
template <class Offer>
void for_each_wall(const Container& c, const Eigen::Vector3d& point, Offer&& offer) {
  const bool cylinder = c.shape == ContainerShape::Cylinder;
  for (int a = 0; a < 3; ++a) {
    if (cylinder && a < 2) continue;  // the side of a cylinder is one round wall
    for (int side = 0; side < 2; ++side) {
      if (c.boundary[a][side] != Boundary::Wall) continue;
      const double wall = c.wall_at(a, side);
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      normal[a] = side == 0 ? -1.0 : 1.0;
      offer(static_cast<Wall>(2 * a + side), normal, side == 0 ? point[a] - wall : wall - point[a]);
    }
  }
  if (cylinder) {
    const Eigen::Vector2d axis = c.cylinder_center + c.wall_offset.head<2>();
    const Eigen::Vector2d out = point.head<2>() - axis;
    const double r = out.norm();
    const Eigen::Vector3d normal =
        r > 0 ? Eigen::Vector3d(out[0] / r, out[1] / r, 0.0) : Eigen::Vector3d::UnitX();
    offer(Wall::CylinderSide, normal, c.cylinder_radius - r);
  }
}

}  // namespace

std::optional<WallTouch> nearest_wall(const Container& c, const Eigen::Vector3d& point) {
  std::optional<WallTouch> best;
  for_each_wall(c, point, [&](Wall w, const Eigen::Vector3d& normal, double distance) {
    if (!best || std::abs(distance) < std::abs(best->distance)) best = {w, normal, distance, 1.0};
  });
  return best;
}

std::optional<WallTouch> facing_wall(const Container& c, const Eigen::Vector3d& centre,
                                     const Eigen::Vector3d& to_point) {
  const double length = to_point.norm();
  std::optional<WallTouch> best;
  // The normals at the centre (a point across the cylinder's axis faces the far side), the
  // point's distance along them.
  for_each_wall(c, centre, [&](Wall w, const Eigen::Vector3d& normal, double distance) {
    const double along = to_point.dot(normal);
    const double facing = length > 0.0 ? along / length : 0.0;
    if (!best || facing > best->facing) best = {w, normal, distance - along, facing};
  });
  return best;
}

}  // namespace granpipe::lammps_dump
