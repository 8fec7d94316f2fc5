#include "sphere_grid.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::pores {

SphereGrid::SphereGrid(const std::vector<Eigen::Vector3d>& centres, std::vector<double> radii,
                       double cell)
    : centres_(centres), radii_(std::move(radii)), cell_(cell) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Eigen::Vector3d& x : centres_) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  lo_ = lo;
  for (int a = 0; a < 3; ++a) n_[a] = std::max(1, static_cast<int>((hi[a] - lo[a]) / cell_) + 1);
  for (double r : radii_) largest_radius_ = std::max(largest_radius_, r);
  std::vector<std::size_t> cell_of_sphere(centres_.size());
  start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    cell_of_sphere[i] = index(cell_of(centres_[i]));
    ++start_[cell_of_sphere[i] + 1];
  }
  for (std::size_t k = 1; k < start_.size(); ++k) start_[k] += start_[k - 1];
  order_.resize(centres_.size());
  std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
  for (std::size_t i = 0; i < centres_.size(); ++i)
    order_[next[cell_of_sphere[i]]++] = static_cast<std::uint32_t>(i);
}

std::array<int, 3> SphereGrid::cell_of(const Eigen::Vector3d& x) const {
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a) {
    // Clamped before the cast: a sliver's tangent sphere reaches 10^9 cells and more.
    c[a] = static_cast<int>(
        std::clamp(std::floor((x[a] - lo_[a]) / cell_), 0.0, static_cast<double>(n_[a] - 1)));
  }
  return c;
}

std::size_t SphereGrid::index(const std::array<int, 3>& c) const {
  return (static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
}

std::vector<std::uint32_t> SphereGrid::overlapping(const Eigen::Vector3d& centre, double radius,
                                                   double length) const {
  std::vector<std::uint32_t> found;
  for_each_overlapping(centre, radius, length, [&](std::uint32_t i) {
    found.push_back(i);
    return true;
  });
  return found;
}

}  // namespace granpipe::pores
