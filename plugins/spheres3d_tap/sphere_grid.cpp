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

bool SphereGrid::any_within(const Eigen::Vector3d& x, double reach, std::int32_t self,
                            const std::vector<Eigen::Vector3d>& centres) const {
  int x0, x1, y0, y1;
  axis_range(x.x() - reach, x.x() + reach, x0, x1);
  axis_range(x.y() - reach, x.y() + reach, y0, y1);
  const int z0 = layer_of(x.z() - reach),
            z1 = std::min(floor_int((x.z() + reach) * inv_cell_), layers_ - 1);
  const double reach2 = reach * reach;
  for (int iz = z0; iz <= z1; ++iz) {
    for (int iy = y0; iy <= y1; ++iy) {
      const int wy = ((iy % n_) + n_) % n_;
      const double shift_y = box_.side * static_cast<double>((iy - wy) / n_);
      const std::int32_t* row = cells_.data() + (static_cast<std::size_t>(iz) * n_ + wy) * n_;
      for (int ix = x0; ix <= x1; ++ix) {
        const int wx = ((ix % n_) + n_) % n_;
        const std::int32_t j = row[wx];
        if (j == kEmpty || j == self) continue;
        const Eigen::Vector3d& c = centres[static_cast<std::size_t>(j)];
        const double dx = c.x() + box_.side * static_cast<double>((ix - wx) / n_) - x.x();
        const double dy = c.y() + shift_y - x.y(), dz = c.z() - x.z();
        if (dx * dx + dy * dy + dz * dz < reach2) return true;
      }
    }
  }
  return false;
}

void SphereGrid::axis_range(double lo, double hi, int& first, int& last) const {
  first = floor_int(lo * inv_cell_);
  last = floor_int(hi * inv_cell_);
  if (box_.periodic()) return;
  first = std::max(first, 0);
  last = std::min(last, n_ - 1);
}

}  // namespace granpipe::spheres3d_tap
