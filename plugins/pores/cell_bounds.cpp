#include "cell_bounds.hpp"

#include <algorithm>
#include <limits>

#include "pore_region.hpp"

namespace granpipe::pores {

CellBounds::CellBounds(const Frame& frame, double tolerance, const Skin& skin)
    : box_lo_(frame.container.lo), box_hi_(frame.container.hi), skin_(skin) {
  const Container& c = frame.container;
  constexpr double infinity = std::numeric_limits<double>::infinity();
  cylinder_ = c.shape == ContainerShape::Cylinder;
  axis_ = c.cylinder_center + c.wall_offset.head<2>();
  cylinder_limit_ = c.cylinder_radius + tolerance;
  for (int a = 0; a < 3; ++a) {
    periodic_[a] = c.periodic(a);
    for (int high = 0; high < 2; ++high) {
      const double outward = high ? 1.0 : -1.0;
      const Boundary b = c.boundary[a][high];
      const bool free = b == Boundary::Periodic || (cylinder_ && a < 2);
      const bool wall = !free && b == Boundary::Wall;
      const double side = free ? 0.0 : packing_side(frame, a, high);
      // Open sides end at the packing's surface: a cell reaching beyond it is not enclosed
      // by particles, and its volume would count the space above the packing.
      limit_[a][high] = free ? outward * infinity : side + outward * tolerance;
      flag_[a][high] = free ? 0 : wall ? kBeyondWall : kOutside;
      plane_walls_ = plane_walls_ || wall;
      // Beyond the container's length past an open side's limit, or past the periodic box
      // or the cylinder, whose cells never reach that far (or are outside). In the
      // container's own scale: a margin of 1 in file units cut the cells of spheres of
      // radius 1e-15 with planes 1e14 cells away, and their volumes were 11 % off.
      const double beyond = 2.0 * c.length(a) + (cylinder_ ? 2.0 * cylinder_limit_ : 0.0);
      const double free_side = cylinder_ && a < 2 ? axis_[a] : high ? c.hi[a] : c.lo[a];
      cut_box_[high][a] = wall   ? side
                          : free ? free_side + outward * beyond
                                 : limit_[a][high] + outward * beyond;
    }
  }
}

std::uint8_t CellBounds::breach(const Eigen::Vector3d& c) const {
  std::uint8_t flags = 0;
  for (int a = 0; a < 3; ++a) {
    if (c[a] < limit_[a][0]) flags |= flag_[a][0];
    if (c[a] > limit_[a][1]) flags |= flag_[a][1];
  }
  if (cylinder_ && (c.head<2>() - axis_).squaredNorm() > cylinder_limit_ * cylinder_limit_)
    flags |= kOutside;
  if ((flags & kOutside) && !(flags & kBeyondWall)) flags |= kOutsideWithinWalls;
  return flags;
}

double CellBounds::periodic_shortfall(const Eigen::Vector3d& c, double reach) const {
  double overshoot = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (!periodic_[a]) continue;
    overshoot = std::max({overshoot, box_lo_[a] - (c[a] - reach), c[a] + reach - box_hi_[a]});
  }
  return overshoot > 0.0 ? std::max(0.0, overshoot - skin_.around(c, reach)) : 0.0;
}

}  // namespace granpipe::pores
