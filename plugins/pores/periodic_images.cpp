#include "periodic_images.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace granpipe::pores {

namespace {

// The bits of a 10-bit integer spread to every third bit.
std::uint32_t spread(std::uint32_t v) {
  v = (v | (v << 16)) & 0x030000FF;
  v = (v | (v << 8)) & 0x0300F00F;
  v = (v | (v << 4)) & 0x030C30C3;
  return (v | (v << 2)) & 0x09249249;
}

// The particles along a Morton (Z-order) curve through their bounding box: rows of nearby
// centres are then near each other, and so are the data kept per point, which the passes
// over the triangulation's cells read in the cells' order.
std::vector<std::uint32_t> spatial_order(const std::vector<Eigen::Vector3d>& x) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3d& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d scale = 1023.0 * (hi - lo).cwiseMax(1e-300).cwiseInverse();
  std::vector<std::uint32_t> key(x.size()), order(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Eigen::Vector3d q = (x[k] - lo).cwiseProduct(scale);
    key[k] = spread(static_cast<std::uint32_t>(q[0])) |
             spread(static_cast<std::uint32_t>(q[1])) << 1 |
             spread(static_cast<std::uint32_t>(q[2])) << 2;
  }
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  return order;
}

// The shifts along one axis that bring coordinate x within `skin` of the box's other side.
std::vector<double> shifts_along(const Container& c, int a, double x, double skin) {
  std::vector<double> shifts{0.0};
  if (!c.periodic(a)) return shifts;
  if (x < c.lo[a] + skin) shifts.push_back(c.length(a));
  if (x >= c.hi[a] - skin) shifts.push_back(-c.length(a));
  return shifts;
}

}  // namespace

Centres centres_with_images(const Frame& frame, double skin) {
  const Container& c = frame.container;
  const auto n = static_cast<std::size_t>(frame.size());
  std::vector<Eigen::Vector3d> wrapped(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a)
      wrapped[k][a] = c.wrap(a, frame.position()(static_cast<Eigen::Index>(k), a));
  Centres centres;
  centres.points.reserve(n);
  centres.particle.reserve(n);
  centres.primary.resize(n);
  for (std::uint32_t k : spatial_order(wrapped)) {
    const Eigen::Vector3d& x = wrapped[k];
    const auto sx = shifts_along(c, 0, x[0], skin), sy = shifts_along(c, 1, x[1], skin),
               sz = shifts_along(c, 2, x[2], skin);
    centres.primary[k] = static_cast<std::uint32_t>(centres.points.size());  // shift 0 first
    for (double dx : sx)
      for (double dy : sy)
        for (double dz : sz) {
          centres.points.push_back(x + Eigen::Vector3d(dx, dy, dz));
          centres.particle.push_back(k);
        }
  }
  return centres;
}

}  // namespace granpipe::pores
