#include "granpipe/container_check.hpp"

#include <cmath>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

namespace {

void require_finite(double value, const std::string& what, const std::string& where) {
  if (std::isfinite(value)) return;
  throw InputError(where + ": expected a finite " + what + " of the container, got " +
                   format_number(value));
}

}  // namespace

void check_container_values(const Container& c, int dim, const std::string& where) {
  for (int a = 0; a < dim; ++a) {
    const std::string axis(1, "xyz"[a]);
    require_finite(c.lo[a], "lower side along " + axis, where);
    require_finite(c.hi[a], "upper side along " + axis, where);
    require_finite(c.wall_offset[a], "wall offset along " + axis, where);
    require_finite(c.wall_velocity[a], "wall velocity along " + axis, where);
    // A periodic axis joins its two ends: periodic at one and a wall at the other was read
    // as periodic by the measures and as a wall by the overlap check.
    if ((c.boundary[a][0] == Boundary::Periodic) != (c.boundary[a][1] == Boundary::Periodic)) {
      throw InputError(where + ": expected both sides along " + axis +
                       " periodic or neither (a periodic axis joins its ends), got " +
                       to_string(c.boundary[a][0]) + " and " + to_string(c.boundary[a][1]));
    }
    if (!(c.lo[a] < c.hi[a])) {
      throw InputError(where + ": expected the container's sides along " + axis +
                       " in order (lo < hi), got " + format_number(c.lo[a]) + " to " +
                       format_number(c.hi[a]));
    }
  }
  // Finite sides, a volume that is not: a base at -1e308 gave the box the volume inf, and
  // packing reported phi = 0 for the bed in it.
  double volume = 1.0;
  std::string sides;
  for (int a = 0; a < dim; ++a) {
    volume *= c.hi[a] - c.lo[a];
    sides += (a ? " x " : "") + format_number(c.hi[a] - c.lo[a]);
  }
  if (!std::isfinite(volume)) {
    throw InputError(where + ": expected a container of finite " + (dim == 2 ? "area" : "volume") +
                     ", got sides of " + sides);
  }
  if (c.shape != ContainerShape::Cylinder) return;
  require_finite(c.cylinder_center[0], "cylinder axis x", where);
  require_finite(c.cylinder_center[1], "cylinder axis y", where);
  if (!(c.cylinder_radius > 0.0) || !std::isfinite(c.cylinder_radius)) {
    throw InputError(where + ": expected a finite cylinder radius > 0, got " +
                     format_number(c.cylinder_radius));
  }
}

bool has_wall(const Container& c, int dim, Wall w) {
  const bool cylinder = c.shape == ContainerShape::Cylinder && dim == 3;
  if (w == Wall::CylinderSide) return cylinder;
  const int axis = static_cast<int>(w) / 2, side = static_cast<int>(w) % 2;
  if (axis >= dim || (cylinder && axis < 2)) return false;
  return c.boundary[axis][side] == Boundary::Wall;
}

std::string walls_not_at_rest(const Container& c, int dim) {
  if (c.wall_offset.head(dim).norm() != 0.0)
    return "its walls displaced by " + format_point(c.wall_offset.head(dim), 17);
  if (c.wall_velocity.head(dim).norm() != 0.0)
    return "its walls moving at " + format_point(c.wall_velocity.head(dim), 17);
  return "";
}

}  // namespace granpipe
