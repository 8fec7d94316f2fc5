#include "granpipe/container.hpp"

#include <cmath>
#include <limits>

namespace granpipe {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::Wall: return "wall";
    case Boundary::Periodic: return "periodic";
    case Boundary::Open: return "open";
  }
  return "?";
}

const char* to_string(ContainerShape s) {
  return s == ContainerShape::Box ? "box" : "cylinder";
}

const char* to_string(Wall w) {
  static const char* names[] = {"x_low", "x_high", "y_low", "y_high", "z_low", "z_high",
                                "cylinder"};
  const auto k = static_cast<unsigned>(w);
  return k < static_cast<unsigned>(Wall::Count) ? names[k] : "?";
}

Container Container::periodic_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Container c;
  c.lo = lo;
  c.hi = hi;
  for (int a = 0; a < dim; ++a) c.boundary[a] = {Boundary::Periodic, Boundary::Periodic};
  return c;
}

Container Container::open_top_box(int dim, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Container c;
  c.lo = lo;
  c.hi = hi;
  c.boundary[dim - 1][1] = Boundary::Open;
  return c;
}

namespace {

// How far a sphere of radius a reaches past each wall of c, the deepest first; the
// depth is negative when it is clear of every wall.
ParticleOutside deepest_wall(const Container& c, int dim, const Eigen::Vector3d& x, double a) {
  ParticleOutside deepest{0, Wall::Count, -std::numeric_limits<double>::infinity()};
  const auto consider = [&](Wall w, double depth) {
    if (depth > deepest.depth) deepest = {0, w, depth};
  };
  const bool cylinder = c.shape == ContainerShape::Cylinder && dim == 3;
  for (int axis = 0; axis < dim; ++axis) {
    if (cylinder && axis < 2) continue;  // the cylinder's sides are not planes
    const double shift = c.wall_offset[axis];
    if (c.boundary[axis][0] == Boundary::Wall) {
      consider(static_cast<Wall>(2 * axis), a - (x[axis] - (c.lo[axis] + shift)));
    }
    if (c.boundary[axis][1] == Boundary::Wall) {
      consider(static_cast<Wall>(2 * axis + 1), a - ((c.hi[axis] + shift) - x[axis]));
    }
  }
  if (cylinder) {
    const double rho = std::hypot(x[0] - c.cylinder_center[0] - c.wall_offset[0],
                                  x[1] - c.cylinder_center[1] - c.wall_offset[1]);
    consider(Wall::CylinderSide, a - (c.cylinder_radius - rho));
  }
  return deepest;
}

}  // namespace

std::optional<ParticleOutside> first_particle_outside(const Container& c, int dim,
                                                      const Eigen::ArrayXXd& position,
                                                      const Eigen::ArrayXd& radius,
                                                      double tolerance) {
  for (Eigen::Index i = 0; i < position.rows(); ++i) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int axis = 0; axis < dim; ++axis) x[axis] = position(i, axis);
    ParticleOutside deepest = deepest_wall(c, dim, x, radius[i]);
    if (deepest.depth > tolerance * radius[i]) {
      deepest.index = i;
      return deepest;
    }
  }
  return std::nullopt;
}

}  // namespace granpipe
