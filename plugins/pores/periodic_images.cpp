#include "periodic_images.hpp"

#include <algorithm>
#include <limits>
#include <utility>

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
  // (key, row) pairs sorted themselves, not rows compared by keys looked up elsewhere.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const Eigen::Vector3d q = (x[k] - lo).cwiseProduct(scale);
    keyed[k] = {spread(static_cast<std::uint32_t>(q[0])) |
                    spread(static_cast<std::uint32_t>(q[1])) << 1 |
                    spread(static_cast<std::uint32_t>(q[2])) << 2,
                static_cast<std::uint32_t>(k)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) order[k] = keyed[k].second;
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

bool within(const Container& c, const Eigen::Vector3d& x, const Eigen::Vector3d& shift,
            double skin) {
  for (int a = 0; a < 3; ++a) {
    const auto s = shifts_along(c, a, x[a], skin);
    if (std::find(s.begin(), s.end(), shift[a]) == s.end()) return false;
  }
  return true;
}

// Particle k at x and its images within `skin` of the sides, but those within `thinner`
// (0: none of them; the unshifted point is within every skin).
void add_images(Centres& to, const Container& c, std::uint32_t k, const Eigen::Vector3d& x,
                double skin, double thinner) {
  const auto sx = shifts_along(c, 0, x[0], skin), sy = shifts_along(c, 1, x[1], skin),
             sz = shifts_along(c, 2, x[2], skin);
  for (double dx : sx)
    for (double dy : sy)
      for (double dz : sz) {
        const Eigen::Vector3d shift(dx, dy, dz);
        if (thinner > 0.0 && within(c, x, shift, thinner)) continue;
        to.points.push_back(x + shift);
        to.particle.push_back(k);
      }
}

// The points in the order of spatial_order (no primary rows).
Centres in_spatial_order(const Centres& c) {
  Centres sorted;
  sorted.points.reserve(c.points.size());
  sorted.particle.reserve(c.points.size());
  for (std::uint32_t row : spatial_order(c.points)) {
    sorted.points.push_back(c.points[row]);
    sorted.particle.push_back(c.particle[row]);
  }
  return sorted;
}

std::vector<Eigen::Vector3d> wrapped_centres(const Frame& frame) {
  const Container& c = frame.container;
  std::vector<Eigen::Vector3d> wrapped(static_cast<std::size_t>(frame.size()));
  for (std::size_t k = 0; k < wrapped.size(); ++k)
    for (int a = 0; a < 3; ++a)
      wrapped[k][a] = c.wrap(a, frame.position()(static_cast<Eigen::Index>(k), a));
  return wrapped;
}

}  // namespace

Centres centres_with_images(const Frame& frame, const Skin& skin) {
  const std::vector<Eigen::Vector3d> wrapped = wrapped_centres(frame);
  Centres all;
  for (std::uint32_t k = 0; k < wrapped.size(); ++k)
    add_images(all, frame.container, k, wrapped[k], skin.at(wrapped[k]), 0.0);
  Centres centres = in_spatial_order(all);
  centres.primary.resize(wrapped.size());
  for (std::uint32_t row = 0; row < centres.points.size(); ++row) {
    const std::uint32_t k = centres.particle[row];
    if (centres.points[row] == wrapped[k]) centres.primary[k] = row;  // the unshifted point
  }
  return centres;
}

Centres images_between(const Frame& frame, const Skin& thinner, const Skin& skin) {
  const std::vector<Eigen::Vector3d> wrapped = wrapped_centres(frame);
  Centres images;
  for (std::uint32_t k = 0; k < wrapped.size(); ++k)
    add_images(images, frame.container, k, wrapped[k], skin.at(wrapped[k]), thinner.at(wrapped[k]));
  return in_spatial_order(images);
}

}  // namespace granpipe::pores
