#include "pore_region.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "granpipe/errors.hpp"

namespace granpipe::pores {

namespace {

const char* axis_name(int a) { return a == 0 ? "x" : a == 1 ? "y" : "z"; }

void check_inside(const Region& r, double top, const RegionSettings& s, const std::string& where) {
  for (int a = 0; a < 3; ++a) {
    if (r.hi[a] > r.lo[a] && (a < 2 || r.hi[a] <= top)) continue;
    std::ostringstream m;
    m << where << ": expected a region of positive size below the top of the packing (" << top
      << "), got " << axis_name(a) << " from " << r.lo[a] << " to " << r.hi[a] << " (margin "
      << s.margin << ", height " << s.height << " radii)";
    throw InputError(m.str());
  }
}

}  // namespace

double packing_side(const Frame& f, int axis, int high) {
  const Container& c = f.container;
  const Boundary b = c.boundary[axis][high];
  if (b == Boundary::Open) {
    return high ? (f.position().col(axis) + f.radius()).maxCoeff()
                : (f.position().col(axis) - f.radius()).minCoeff();
  }
  const double wall = high ? c.hi[axis] : c.lo[axis];
  return b == Boundary::Wall ? wall + c.wall_offset[axis] : wall;
}

bool in_box(const Region& r, const Eigen::Vector3d& x) {
  for (int a = 0; a < 3; ++a)
    if (!(x[a] >= r.lo[a] && x[a] < r.hi[a])) return false;
  return true;
}

bool PoreRegion::contains(const Eigen::Vector3d& x) const {
  return in_box(box, x) && (x.head<2>() - axis).squaredNorm() < radius * radius;
}

namespace {

// The cylinder's radius less the margin, about its axis where the walls have moved it.
void shrink_to_cylinder(const Container& c, double margin, PoreRegion& region,
                        const std::string& where) {
  region.axis = c.cylinder_center + c.wall_offset.head<2>();
  region.radius = c.cylinder_radius - margin;
  if (region.radius > 0.0) return;
  std::ostringstream m;
  m << where << ": expected a margin below the cylinder's radius " << c.cylinder_radius << ", got "
    << margin;
  throw InputError(m.str());
}

}  // namespace

std::optional<PoreRegion> pore_region(const Frame& frame, const RegionSettings& s, double radius,
                                      const std::string& where) {
  const bool periodic =
      frame.container.periodic(0) && frame.container.periodic(1) && frame.container.periodic(2);
  if (s.kind == RegionKind::All) {
    if (periodic) return std::nullopt;
    // The container itself: the slivers of the convex hull along its walls and open sides
    // have centres far outside (below the base, ξ up to 10^5), and counting them made ν
    // 10^10 to 10^27 with exit 0. Open at both ends along its bounded axes: a crystal's
    // surface cells centred on two mirror walls were counted on the lower one only.
    std::optional<PoreRegion> all =
        pore_region(frame, {RegionKind::Inner, 0.0, 0.0}, radius, where);
    for (int a = 0; a < 3; ++a)
      if (!frame.container.periodic(a))
        all->box.lo[a] = std::nextafter(all->box.lo[a], all->box.hi[a]);
    return all;
  }
  // Periodic on every side, "inner" is "all" whatever its margin (a margin of 100 radii
  // changed nothing, exit 0), as a height is along a periodic z.
  if (periodic) {
    throw InputError(where +
                     ": expected region \"all\" for a container periodic on every side (an "
                     "inner region keeps its margin from walls, and it has none), got \"inner\"");
  }
  PoreRegion inner;
  if (frame.container.shape == ContainerShape::Cylinder)
    shrink_to_cylinder(frame.container, s.margin * radius, inner, where);
  Region& r = inner.box;
  r.dim = 3;
  for (int a = 0; a < 3; ++a) {
    // Along a periodic axis every pore is in the region once (measure_pores picks one image).
    const double reach =
        frame.container.periodic(a) ? std::numeric_limits<double>::infinity() : -s.margin * radius;
    r.lo[a] = packing_side(frame, a, 0) - reach;
    r.hi[a] = packing_side(frame, a, 1) + reach;
  }
  const double top = r.hi[2];
  if (s.height > 0.0 && frame.container.periodic(2)) {
    throw InputError(where + ": expected height 0 for a container periodic along z, got " +
                     std::to_string(s.height));
  }
  if (s.height > 0.0) r.hi[2] = r.lo[2] + s.height * radius;
  check_inside(r, top, s, where);
  return inner;
}

}  // namespace granpipe::pores
