#include "walls.hpp"

#include <cmath>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe::dem {

WallSet::WallSet(const Container& rest, const Drive& drive) : rest_(rest) {
  set_drive(drive);
  cylinder_ = rest.shape == ContainerShape::Cylinder;
  if (cylinder_ && !(std::isfinite(rest.cylinder_radius) && rest.cylinder_radius > 0.0)) {
    std::ostringstream s;
    s << "dem: container: cylinder radius: expected a finite value > 0, got "
      << rest.cylinder_radius;
    throw InputError(s.str());
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const Boundary b = rest.boundary[axis][side];
      if (b == Boundary::Periodic) {
        throw InputError(std::string("dem: container: ") +
                         to_string(static_cast<Wall>(2 * axis + side)) +
                         ": expected a wall or an open side, got a periodic side (the DEM "
                         "engine has no periodic boundaries)");
      }
      if (b != Boundary::Wall || (cylinder_ && axis < 2)) continue;
      const double position = side == 0 ? rest.lo[axis] : rest.hi[axis];
      if (!std::isfinite(position)) {
        std::ostringstream s;
        s << "dem: container: " << to_string(static_cast<Wall>(2 * axis + side))
          << ": expected a finite position, got " << position;
        throw InputError(s.str());
      }
      planes_.push_back(
          {static_cast<Wall>(2 * axis + side), axis, side == 0 ? 1.0 : -1.0, position});
    }
  }
}

void WallSet::set_drive(const Drive& drive) {
  drive.check();
  drive_ = drive;
}

Wall WallSet::wall_of_slot(int slot) const {
  return slot < static_cast<int>(planes_.size()) ? planes_[slot].wall : Wall::CylinderSide;
}

double WallSet::overlap(int slot, const Eigen::Vector3d& x, double a, const Eigen::Vector3d& offset,
                        Eigen::Vector3d& normal) const {
  normal.setZero();
  if (slot < static_cast<int>(planes_.size())) {
    const PlaneWall& p = planes_[slot];
    normal[p.axis] = p.sign;
    return plane_overlap(p.sign, x[p.axis], p.rest_position + offset[p.axis], a);
  }
  const double dx = x[0] - (rest_.cylinder_center[0] + offset[0]);
  const double dy = x[1] - (rest_.cylinder_center[1] + offset[1]);
  double rho = 0.0;
  const double delta = cylinder_overlap(dx, dy, rest_.cylinder_radius, a, rho);
  if (rho > 0.0) normal = Eigen::Vector3d(-dx / rho, -dy / rho, 0.0);
  return delta;
}

Container WallSet::at(double t) const {
  Container c = rest_;
  c.wall_offset = drive_.offset(t);
  c.wall_velocity = drive_.velocity(t);
  return c;
}

}  // namespace granpipe::dem
