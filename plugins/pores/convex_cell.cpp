#include "convex_cell.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>

namespace granpipe::pores {

namespace {

// Where the edge ab crosses the plane (s: normal . x - offset at each end), computed from
// the end that sorts first: the two faces that share the edge then make the same point.
Eigen::Vector3d crossing(const Eigen::Vector3d& a, double sa, const Eigen::Vector3d& b, double sb) {
  if (std::lexicographical_compare(b.begin(), b.end(), a.begin(), a.end()))
    return b + (a - b) * (sb / (sb - sa));
  return a + (b - a) * (sa / (sa - sb));
}

// A number that grows with the angle of (x, y) from the x axis, from 0 to 4 around the
// circle: orders points by angle without trigonometry.
double pseudo_angle(double x, double y) {
  const double sum = std::abs(x) + std::abs(y);
  if (sum == 0.0) return 0.0;
  const double t = y / sum;  // -1 ... 1, like the sine
  return x >= 0.0 ? (y >= 0.0 ? t : 4.0 + t) : 2.0 - t;
}

double farthest_squared(const std::vector<Eigen::Vector3d>& corners) {
  double farthest = 0.0;
  for (const Eigen::Vector3d& c : corners) farthest = std::max(farthest, c.squaredNorm());
  return farthest;
}

}  // namespace

void ConvexCell::reset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  // Corner numbers (bit a: the upper side of axis a) of each side, counter-clockwise seen
  // from outside.
  constexpr int kSides[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  corners_.clear();
  sizes_.clear();
  for (const auto& side : kSides) {
    for (int i : side)
      corners_.emplace_back(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
    sizes_.push_back(4);
  }
  farthest_squared_ = farthest_squared(corners_);
}

void ConvexCell::cut(const Eigen::Vector3d& normal, double offset) {
  // No corner is farther than the plane: nothing to cut (most neighbours, once the
  // nearest have cut the cell down).
  if (offset > 0.0 && offset * offset >= farthest_squared_ * normal.squaredNorm()) return;
  side_.resize(corners_.size());
  bool some_out = false, all_out = true;
  for (std::size_t k = 0; k < corners_.size(); ++k) {
    side_[k] = normal.dot(corners_[k]) - offset;
    some_out = some_out || side_[k] > 0.0;
    all_out = all_out && side_[k] > 0.0;
  }
  if (!some_out) return;
  if (all_out) {
    corners_.clear();
    sizes_.clear();
    return;
  }
  kept_corners_.clear();
  kept_sizes_.clear();
  lid_.clear();
  std::size_t first = 0;
  for (int size : sizes_) {
    const std::size_t before = kept_corners_.size();
    for (int k = 0; k < size; ++k) {
      const std::size_t a = first + k, b = first + (k + 1) % size;
      const double sa = side_[a], sb = side_[b];
      if (sa <= 0.0) kept_corners_.push_back(corners_[a]);
      if (sa == 0.0) lid_.push_back(corners_[a]);
      if ((sa <= 0.0) == (sb <= 0.0) || sa == 0.0 || sb == 0.0) continue;
      kept_corners_.push_back(crossing(corners_[a], sa, corners_[b], sb));
      lid_.push_back(kept_corners_.back());
    }
    const auto kept = static_cast<int>(kept_corners_.size() - before);
    if (kept >= 3) {
      kept_sizes_.push_back(kept);
    } else {
      kept_corners_.resize(before);
    }
    first += static_cast<std::size_t>(size);
  }
  close(normal);
  std::swap(corners_, kept_corners_);
  std::swap(sizes_, kept_sizes_);
  farthest_squared_ = farthest_squared(corners_);
}

// Counter-clockwise around the normal, which points out of the part kept.
void ConvexCell::close(const Eigen::Vector3d& normal) {
  if (lid_.size() < 3) return;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& c : lid_) centre += c;
  centre /= static_cast<double>(lid_.size());
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.normalized().cross(u);
  by_angle_.clear();
  for (std::size_t k = 0; k < lid_.size(); ++k) {
    const Eigen::Vector3d d = lid_[k] - centre;
    by_angle_.emplace_back(pseudo_angle(d.dot(u), d.dot(v)), static_cast<int>(k));
  }
  std::sort(by_angle_.begin(), by_angle_.end());
  const std::size_t before = kept_corners_.size();
  for (const auto& [angle, k] : by_angle_) {
    // The faces that meet at a corner each gave it.
    if (kept_corners_.size() == before || lid_[k] != kept_corners_.back())
      kept_corners_.push_back(lid_[k]);
  }
  if (kept_corners_.size() - before > 1 && kept_corners_[before] == kept_corners_.back())
    kept_corners_.pop_back();
  const auto kept = static_cast<int>(kept_corners_.size() - before);
  if (kept >= 3) {
    kept_sizes_.push_back(kept);
  } else {
    kept_corners_.resize(before);
  }
}

double ConvexCell::volume() const {
  if (sizes_.empty()) return 0.0;
  const Eigen::Vector3d& o = corners_.front();
  double six_volume = 0.0;
  std::size_t first = 0;
  for (int size : sizes_) {
    const Eigen::Vector3d& f0 = corners_[first];
    for (int k = 1; k + 1 < size; ++k)
      six_volume += (f0 - o).dot((corners_[first + k] - o).cross(corners_[first + k + 1] - o));
    first += static_cast<std::size_t>(size);
  }
  return six_volume / 6.0;
}

}  // namespace granpipe::pores
