#pragma once
// A grid of cubic cells small enough that no two non-overlapping spheres can have their
// centres in one cell (side < 2R / sqrt 3), so each cell holds one sphere index or none:
// O(1) moves and flat-array queries, no lists: the Monte Carlo moves one sphere per
// accepted trial and asks for the neighbours of one when its list is renewed. Cells cover the box's
// cross-section; layers are added upwards as the packing grows. Along periodic sides queries wrap
// and report the image's shift.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

class SphereGrid {
 public:
  static constexpr std::int32_t kEmpty = -1;

  // An empty grid over `box`.
  explicit SphereGrid(const TapBox& box);

  int cell_of(const Eigen::Vector3d& x) const {
    return (layer_of(x.z()) * n_ + index_of(x.y())) * n_ + index_of(x.x());
  }
  // Puts sphere i at the cell of x (adding layers as needed); throws InternalError when
  // another sphere is there already (which only overlapping spheres can cause).
  void put(std::int32_t i, const Eigen::Vector3d& x);
  void erase(const Eigen::Vector3d& x) { cells_[static_cast<std::size_t>(cell_of(x))] = kEmpty; }

  // Calls f(j, shift) for every sphere whose centre lies in a cell touching the box
  // [lo, hi]; the centre's image there is x_j + shift (shift is zero but along periodic
  // sides). A range wider than a period visits a sphere once per image it covers.
  template <class F>
  void for_each_in(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, F&& f) const;

 private:
  // A cell index taken back into [0, n) along a periodic side, and the image shift that
  // takes a centre in that cell to the unwrapped one.
  struct Wrapped {
    int index;
    double shift;
    void step(int n, double side) {
      if (++index == n) {
        index = 0;
        shift += side;
      }
    }
  };
  Wrapped wrapped(int i) const {
    const int w = ((i % n_) + n_) % n_;
    return {w, box_.side * static_cast<double>((i - w) / n_)};
  }
  static int floor_int(double v) {
    const int t = static_cast<int>(v);
    return t - (v < static_cast<double>(t));
  }
  int index_of(double x) const { return std::clamp(floor_int(x * inv_cell_), 0, n_ - 1); }
  int layer_of(double z) const { return std::max(floor_int(z * inv_cell_), 0); }
  // Cells [first, last] along x or y, clamped to the box with walls.
  void axis_range(double lo, double hi, int& first, int& last) const;

  TapBox box_;
  double cell_ = 1.0, inv_cell_ = 1.0;
  int n_ = 1;       // cells along x and along y
  int layers_ = 0;  // cells along z so far
  std::vector<std::int32_t> cells_;
};

template <class F>
void SphereGrid::for_each_in(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, F&& f) const {
  int x0, x1, y0, y1;
  axis_range(lo.x(), hi.x(), x0, x1);
  axis_range(lo.y(), hi.y(), y0, y1);
  const int z0 = layer_of(lo.z()), z1 = std::min(floor_int(hi.z() * inv_cell_), layers_ - 1);
  // Wrapped indices step along with the unwrapped ones: no division in the loops over
  // the few hundred cells of a query.
  const Wrapped first_x = wrapped(x0), first_y = wrapped(y0);
  for (int iz = z0; iz <= z1; ++iz) {
    Wrapped y = first_y;
    for (int iy = y0; iy <= y1; ++iy, y.step(n_, box_.side)) {
      const std::int32_t* row = cells_.data() + (static_cast<std::size_t>(iz) * n_ + y.index) * n_;
      Wrapped x = first_x;
      for (int ix = x0; ix <= x1; ++ix, x.step(n_, box_.side)) {
        const std::int32_t j = row[x.index];
        if (j != kEmpty) f(j, Eigen::Vector3d(x.shift, y.shift, 0.0));
      }
    }
  }
}

}  // namespace granpipe::spheres3d_tap
