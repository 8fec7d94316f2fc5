#include "pore_region.hpp"

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

std::optional<Region> pore_region(const Frame& frame, const RegionSettings& s, double radius,
                                  const std::string& where) {
  if (s.kind == RegionKind::All) return std::nullopt;
  if (frame.container.shape != ContainerShape::Box) {
    throw InputError(where + ": region \"inner\" expected a box container, got a " +
                     to_string(frame.container.shape) + " (use region \"all\")");
  }
  Region r;
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
  return r;
}

}  // namespace granpipe::pores
