#include "disk_grid.hpp"

#include <string>

#include "granpipe/errors.hpp"

namespace granpipe::disks2d_tap {

void DiskGrid::reset(double width, double height, double cell, double margin) {
  width_ = width;
  height_ = height;
  cell_ = cell;
  inv_cell_ = 1.0 / cell;
  ncol_ = static_cast<int>(std::floor(width * inv_cell_)) + 1;
  nrow_ = static_cast<int>(std::floor(height * inv_cell_)) + 1;
  pad_ = static_cast<int>(std::ceil(margin * inv_cell_)) + 1;
  stride_ = ncol_ + 2 * pad_;
  cells_.assign(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(nrow_ + 2 * pad_),
                kEmpty);
}

void DiskGrid::put(std::int32_t i, int cell) {
  auto& slot = cells_[static_cast<std::size_t>(cell)];
  if (slot != kEmpty && slot != i) {
    throw InternalError("disks2d_tap: disks " + std::to_string(slot) + " and " + std::to_string(i) +
                        " share a grid cell, so they overlap");
  }
  slot = i;
}

}  // namespace granpipe::disks2d_tap
