#include "granpipe/particles_outside.hpp"

#include <cmath>

#include "granpipe/format_number.hpp"

namespace granpipe {

namespace {

// The plane sides that bound particles: every Wall (and Open, when they bound) side of the
// frame's axes, but the x and y sides of a cylinder container, whose cylinder holds the
// particles instead.
bool bounds(const Container& c, int dim, int axis, int side, bool open_sides_bound) {
  if (c.shape == ContainerShape::Cylinder && axis < 2) return false;
  const Boundary b = c.boundary[axis][side];
  return axis < dim && (b == Boundary::Wall || (b == Boundary::Open && open_sides_bound));
}

// How far particle k's centre lies inside the wall (or open side) w of container c.
double centre_inside(const Frame& f, const Container& c, Eigen::Index k, Wall w) {
  if (w == Wall::CylinderSide) {
    const double dx = f.position()(k, 0) - c.cylinder_center[0] - c.wall_offset[0];
    const double dy = f.position()(k, 1) - c.cylinder_center[1] - c.wall_offset[1];
    return c.cylinder_radius - std::hypot(dx, dy);
  }
  const int axis = static_cast<int>(w) / 2, side = static_cast<int>(w) % 2;
  return (side == 0 ? 1.0 : -1.0) * (f.position()(k, axis) - c.wall_at(axis, side));
}

// How far particle k's surface lies from the wall w of container c.
double gap_to(const Frame& f, const Container& c, Eigen::Index k, Wall w) {
  return centre_inside(f, c, k, w) - f.radius()[k];
}

// How far particle k reaches beyond a side of c (a plane or the cylinder); > allowed means
// outside.
std::optional<ParticleOutside> beyond(const Frame& f, const Container& c, Eigen::Index k, Wall wall,
                                      double tolerance) {
  if (wall != Wall::CylinderSide) {
    const Boundary b = c.boundary[static_cast<int>(wall) / 2][static_cast<int>(wall) % 2];
    if (b == Boundary::Open) {
      const double inward = centre_inside(f, c, k, wall);
      if (inward < 0.0) return ParticleOutside{k, wall, -inward};
      return {};
    }
  }
  const double overlap = -gap_to(f, c, k, wall);
  if (overlap > tolerance * f.radius()[k]) return ParticleOutside{k, wall, overlap};
  return {};
}

std::string where_is(const Container& c, Wall wall) {
  if (wall == Wall::CylinderSide) {
    return "the wall cylinder (radius " + format_number(c.cylinder_radius) + " about (" +
           format_number(c.cylinder_center[0] + c.wall_offset[0]) + ", " +
           format_number(c.cylinder_center[1] + c.wall_offset[1]) + "))";
  }
  const int axis = static_cast<int>(wall) / 2, side = static_cast<int>(wall) % 2;
  const std::string at = std::string(1, "xyz"[axis]) + " = " + format_number(c.wall_at(axis, side));
  const bool open = c.boundary[axis][side] == Boundary::Open;
  return std::string(open ? "the open side " : "the wall ") + to_string(wall) + " (" + at + ")";
}

}  // namespace

double surface_gap(const Frame& frame, Eigen::Index k, Wall w) {
  return gap_to(frame, frame.container, k, w);
}

std::optional<ParticleOutside> first_particle_outside(const Frame& frame, double tolerance,
                                                      bool open_sides_bound) {
  return first_particle_outside(frame, frame.container, tolerance, open_sides_bound);
}

std::optional<ParticleOutside> first_particle_outside(const Frame& frame,
                                                      const Container& container, double tolerance,
                                                      bool open_sides_bound) {
  const bool cylinder = container.shape == ContainerShape::Cylinder && frame.dim == 3;
  for (Eigen::Index k = 0; k < frame.size(); ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int side = 0; side < 2; ++side) {
        if (!bounds(container, frame.dim, axis, side, open_sides_bound)) continue;
        const auto wall = static_cast<Wall>(2 * axis + side);
        if (auto out = beyond(frame, container, k, wall, tolerance)) return out;
      }
    }
    if (cylinder) {
      if (auto out = beyond(frame, container, k, Wall::CylinderSide, tolerance)) return out;
    }
  }
  return {};
}

std::string describe(const Frame& frame, const ParticleOutside& outside, double tolerance) {
  return describe(frame, frame.container, outside, tolerance);
}

std::string describe(const Frame& frame, const Container& container, const ParticleOutside& outside,
                     double tolerance) {
  const Eigen::Index k = outside.particle;
  std::string at;
  for (int a = 0; a < frame.dim; ++a) at += (a ? ", " : "") + format_number(frame.position()(k, a));
  const std::string s = "at (" + at + "), radius " + format_number(frame.radius()[k]) + ": ";
  const auto axis = static_cast<std::size_t>(outside.wall) / 2,
             side = static_cast<std::size_t>(outside.wall) % 2;
  if (outside.wall != Wall::CylinderSide && container.boundary[axis][side] == Boundary::Open) {
    return s + "expected its centre inside " + where_is(container, outside.wall) + ", got it " +
           format_number(outside.depth) + " beyond";
  }
  return s + "expected an overlap with " + where_is(container, outside.wall) + " of at most " +
         format_number(tolerance * frame.radius()[k]) + " (" + format_number(tolerance) +
         " of its radius), got " + format_number(outside.depth);
}

}  // namespace granpipe
