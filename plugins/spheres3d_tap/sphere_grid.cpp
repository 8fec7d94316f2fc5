#include "sphere_grid.hpp"

#include <string>

#include "granpipe/errors.hpp"

namespace granpipe::spheres3d_tap {

SphereGrid::SphereGrid(const TapBox& box) : box_(box) {
  // The largest n with side / n still >= 2R / sqrt(3) is floor(side sqrt(3) / 2R); one
  // more makes the cell strictly smaller, so a cell's diagonal is below 2R.
  n_ = static_cast<int>(std::floor(box.side * std::sqrt(3.0) / (2.0 * box.radius))) + 1;
  cell_ = box.side / n_;
  inv_cell_ = 1.0 / cell_;
}

void SphereGrid::put(std::int32_t i, const Eigen::Vector3d& x) {
  const int layer = layer_of(x.z());
  if (layer >= layers_) {
    layers_ = layer + 1;
    cells_.resize(static_cast<std::size_t>(layers_) * n_ * n_, kEmpty);
  }
  std::int32_t& cell = cells_[static_cast<std::size_t>(cell_of(x))];
  if (cell != kEmpty) {
    throw InternalError("sphere grid: spheres " + std::to_string(cell) + " and " +
                        std::to_string(i) + " in one cell (they overlap)");
  }
  cell = i;
}

void SphereGrid::axis_range(double lo, double hi, int& first, int& last) const {
  first = floor_int(lo * inv_cell_);
  last = floor_int(hi * inv_cell_);
  if (box_.periodic()) return;
  first = std::max(first, 0);
  last = std::min(last, n_ - 1);
}

}  // namespace granpipe::spheres3d_tap
