#include "deposit.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "granpipe/container.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/stop_request.hpp"
#include "roll_path.hpp"

namespace granpipe::spheres3d_tap {

namespace {

// Obstacles within this fraction of R of contact count as touched: far above the
// rounding of the closed-form stops (1e-15), far below any real gap.
constexpr double kTouch = 1e-9;
// A descent takes a few tens of stages; this many means a cycle the geometry cannot
// leave, a bug to report rather than a hang.
constexpr int kMaxStages = 100000;

bool same(const Obstacle& a, const Obstacle& b) {
  if (a.is_plane() || b.is_plane())
    return a.is_plane() && b.is_plane() && a.plane.label == b.plane.label;
  return a.sphere == b.sphere && (a.centre - b.centre).squaredNorm() < 1e-12;
}

std::int64_t label_of(const Obstacle& o) {
  return o.is_plane() ? partner::wall(static_cast<Wall>(o.plane.label)) : o.sphere;
}

}  // namespace

bool at_rest(const std::vector<Obstacle>& supports) {
  for (const auto& s : supports)
    if (s.is_plane() && s.plane.label == static_cast<int>(Wall::ZLow)) return true;
  return supports.size() >= 3;
}

Deposition::Deposition(const TapBox& box)
    : box_(box), planes_(box.centre_planes()), grid_(box), top_(box.radius) {}

std::vector<Obstacle> Deposition::touching(const Eigen::Vector3d& p) const {
  const double reach = 2.0 * box_.radius * (1.0 + kTouch);
  std::vector<Obstacle> found;
  const Eigen::Vector3d lo = p.array() - reach, hi = p.array() + reach;
  grid_.for_each_in(lo, hi, [&](std::int32_t j, const Eigen::Vector3d& shift) {
    const Eigen::Vector3d c = centres_[static_cast<std::size_t>(j)] + shift;
    if ((p - c).norm() <= reach) found.push_back(Obstacle::of_sphere(j, c));
  });
  for (const auto& plane : planes_)
    if (plane.normal.dot(p) - plane.offset <= kTouch * box_.radius)
      found.push_back(Obstacle::of_plane(plane));
  return found;
}

std::vector<Obstacle> Deposition::candidates(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                             const std::vector<Obstacle>& supports) const {
  const double reach = 2.0 * box_.radius;
  std::vector<Obstacle> found;
  auto keep = [&](const Obstacle& o) {
    for (const auto& s : supports)
      if (same(o, s)) return;
    found.push_back(o);
  };
  const Eigen::Vector3d wide_lo = lo.array() - reach, wide_hi = hi.array() + reach;
  grid_.for_each_in(wide_lo, wide_hi, [&](std::int32_t j, const Eigen::Vector3d& shift) {
    keep(Obstacle::of_sphere(j, centres_[static_cast<std::size_t>(j)] + shift));
  });
  for (const auto& plane : planes_) keep(Obstacle::of_plane(plane));
  return found;
}

Eigen::Vector3d Deposition::roll_off(const Eigen::Vector3d& p,
                                     const std::vector<Obstacle>& supports,
                                     const std::vector<Obstacle>& touching,
                                     RandomStream& rng) const {
  Eigen::Vector3d way;
  if (supports.size() == 1) {
    const double azimuth = rng.uniform(0.0, 2.0 * std::numbers::pi);
    way = Eigen::Vector3d(std::cos(azimuth), std::sin(azimuth), 0.0);
  } else {
    // Along the groove's circle: perpendicular to its axis and to the radius at p.
    const Obstacle& sphere = supports[0].is_plane() ? supports[1] : supports[0];
    const Obstacle& other = supports[0].is_plane() ? supports[0] : supports[1];
    const Eigen::Vector3d axis =
        other.is_plane() ? other.plane.normal : Eigen::Vector3d(other.centre - sphere.centre);
    way = axis.cross(p - sphere.centre).normalized();
    if (rng.uniform() < 0.5) way = -way;
  }
  for (const auto& o : touching)
    if (o.is_plane() && o.plane.normal.dot(way) < 0.0) way = -way;
  return way;
}

void Deposition::add(const Eigen::Vector3d& p, const std::vector<Obstacle>& supports) {
  const Eigen::Vector3d x = box_.wrap(p);
  const auto i = static_cast<std::int32_t>(centres_.size());
  grid_.put(i, x);
  centres_.push_back(x);
  Supports labels{partner::none, partner::none, partner::none};
  for (std::size_t k = 0; k < std::min<std::size_t>(supports.size(), 3); ++k)
    labels[k] = label_of(supports[k]);
  supports_.push_back(labels);
  top_ = std::max(top_, x.z());
}

void Deposition::drop(double x, double y, RandomStream& rng) {
  Eigen::Vector3d p(x, y, top_ + 2.0 * box_.radius);
  for (int stage = 0; stage < kMaxStages; ++stage, ++stages_) {
    const std::vector<Obstacle> touch = touching(p);
    const Descent descent = descend(p, touch);
    std::vector<Obstacle> supports;
    for (int k : descent.supports) supports.push_back(touch[static_cast<std::size_t>(k)]);
    Eigen::Vector3d way = descent.direction;
    if (way.isZero()) {
      if (at_rest(supports)) return add(p, supports);
      way = roll_off(p, supports, touch, rng);
    }
    const Path path = path_from(p, way, supports);
    Eigen::Vector3d lo, hi;
    path.bounds(p.z(), lo, hi);
    p = path.at(first_end(path, supports, candidates(lo, hi, supports), box_.radius).t);
  }
  throw InternalError("deposition: sphere " + std::to_string(centres_.size()) +
                      " did not come to rest in " + std::to_string(kMaxStages) + " stages");
}

void Deposition::drop_random(int n, RandomStream& rng) {
  const double lo = box_.periodic() ? 0.0 : box_.radius;
  const double hi = box_.periodic() ? box_.side : box_.side - box_.radius;
  for (int i = 0; i < n; ++i) {
    if (i % 1024 == 0) throw_if_stop_requested();  // a large deposition takes minutes
    const double x = rng.uniform(lo, hi);
    drop(x, rng.uniform(lo, hi), rng);
  }
}

}  // namespace granpipe::spheres3d_tap
