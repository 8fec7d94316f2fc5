#include "skin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pore_region.hpp"

namespace granpipe::pores {

double Skin::at(const Eigen::Vector3d& x) const {
  for (int a = 0; a < 3; ++a)
    if (x[a] <= band[a][0] || x[a] >= band[a][1]) return edge;
  return bulk;
}

double Skin::around(const Eigen::Vector3d& c, double reach) const {
  for (int a = 0; a < 3; ++a)
    if (c[a] + reach <= band[a][0] || c[a] - reach >= band[a][1]) return edge;
  return bulk;
}

Skin Skin::wider(double shortfall, double period) const {
  Skin w = *this;
  w.bulk = std::min(std::max(1.1 * (bulk + shortfall), 1.25 * bulk), period);
  w.edge = std::min(edge + (w.bulk - bulk), period);
  return w;
}

Skin first_skin(const Frame& frame, double radius) {
  constexpr double kBulk = 4.0, kEdge = 10.0, kOpenDepth = 24.0, kWallDepth = 8.0;
  const Container& c = frame.container;
  double period = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
    if (c.periodic(a)) period = std::min(period, c.length(a));
  if (!std::isfinite(period)) return Skin(0.0);
  Skin skin(std::min(kBulk * radius, period));
  skin.edge = std::min(kEdge * radius, period);
  for (int a = 0; a < 3; ++a) {
    if (c.periodic(a)) continue;
    const double extent = packing_side(frame, a, 1) - packing_side(frame, a, 0);
    for (int high = 0; high < 2; ++high) {
      const double depth =
          (c.boundary[a][high] == Boundary::Open ? kOpenDepth : kWallDepth) * radius;
      // A band costs few images only in a packing several times deeper than it: in a
      // shallower one the bulk's width is tried first, and widened as needed.
      if (3.5 * depth > extent) continue;
      skin.band[a][high] = packing_side(frame, a, high) + (high ? -depth : depth);
    }
  }
  return skin;
}

}  // namespace granpipe::pores
