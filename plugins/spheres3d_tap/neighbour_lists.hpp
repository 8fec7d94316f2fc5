#pragma once
// Per-sphere neighbour lists with a skin for the Monte Carlo overlap test: a trial move
// looks at the dozen spheres listed for the mover instead of the ~100 cells of the
// grid around it. Lists are renewed one sphere at a time, when that sphere has strayed,
// so no sweep ever rebuilds them all (only a dilation, which moves every sphere, does).
//
// Invariants, for every sphere i, with |d| the length of a separation d taken to its
// nearest periodic image along periodic sides:
//  - ref_i is where i was when its list was last made, and |x_i - ref_i| <= slack;
//  - j is in list(i) exactly when i is in list(j) exactly when |ref_j - ref_i| < reach.
// A trial position t of i, within `move` of x_i, overlaps a sphere j only when
// |t - x_j| < 2R; then |ref_j - ref_i| < 2R + move + 2 slack = reach, so j is listed.
// The nearest image is the one to test: if any image of j overlaps t, the nearest does
// (in any box at least 2R wide, which also keeps i's own images off it).
//
// Lists are flat, a fixed number of 32-bit indices per sphere (16: one cache line),
// doubled for all when one would overflow: the test is bound by memory, not arithmetic.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "sphere_grid.hpp"
#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

class NeighbourLists {
 public:
  // `move` the longest trial displacement, `slack` how far a sphere may stray from where
  // its list was made.
  NeighbourLists(const TapBox& box, double move, double slack);

  // Lists for all `centres`, which `grid` holds.
  void rebuild(const std::vector<Eigen::Vector3d>& centres, const SphereGrid& grid);
  // True when a sphere of i's list overlaps the position t (within `move` of x_i).
  bool overlaps(std::int32_t i, const Eigen::Vector3d& t,
                const std::vector<Eigen::Vector3d>& centres) const {
    const auto k = static_cast<std::size_t>(i);
    const std::uint32_t* list = entries_.data() + k * capacity_;
    const double contact2 = 4.0 * radius2_;
    for (const std::uint32_t* j = list; j != list + counts_[k]; ++j) {
      const Eigen::Vector3d& c = centres[*j];
      const double dx = nearest(c.x() - t.x()), dy = nearest(c.y() - t.y()), dz = c.z() - t.z();
      if (dx * dx + dy * dy + dz * dz < contact2) return true;
    }
    return false;
  }
  // Starts bringing i's list into the cache, for a trial soon.
  void prefetch(std::int32_t i) const {
    __builtin_prefetch(entries_.data() + static_cast<std::size_t>(i) * capacity_);
  }
  // Sphere i has moved to centres[i], which `grid` holds: renews its list when it has
  // strayed past the slack.
  void moved(std::int32_t i, const std::vector<Eigen::Vector3d>& centres, const SphereGrid& grid) {
    if (distance2(centres[static_cast<std::size_t>(i)], refs_[static_cast<std::size_t>(i)]) >
        slack2_)
      renew(i, centres, grid);
  }
  std::size_t renewals() const { return renewals_; }

 private:
  // A separation along a periodic side taken to the nearest image; a separation between
  // centres in the box, or a move away from one, is within one side of it.
  double nearest(double d) const {
    if (!periodic_) return d;
    if (d > half_side_) return d - side_;
    return d < -half_side_ ? d + side_ : d;
  }
  double distance2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    const double dx = nearest(a.x() - b.x()), dy = nearest(a.y() - b.y()), dz = a.z() - b.z();
    return dx * dx + dy * dy + dz * dz;
  }
  // Makes i's list afresh around its centre, and updates the lists that name it.
  void renew(std::int32_t i, const std::vector<Eigen::Vector3d>& centres, const SphereGrid& grid);
  // Calls f(j) once for every j != i within reach of ref_i.
  template <class F>
  void for_each_near(std::int32_t i, const SphereGrid& grid, F&& f) const;
  bool listed(std::int32_t in, std::int32_t j) const;
  void add(std::int32_t to, std::int32_t j);
  void erase(std::int32_t from, std::int32_t j);

  bool periodic_;
  double side_, half_side_, radius2_, reach2_, range_, slack2_;
  bool images_repeat_;  // a query may show a sphere twice
  std::vector<Eigen::Vector3d> refs_;
  std::size_t capacity_ = 16;
  std::vector<std::uint32_t> entries_;  // capacity_ per sphere
  std::vector<std::uint32_t> counts_;
  std::size_t renewals_ = 0;
};

}  // namespace granpipe::spheres3d_tap
