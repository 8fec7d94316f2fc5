#include "disk_grid.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "granpipe/errors.hpp"

namespace granpipe::disks2d_tap {

// A grid of more cells holds a packing spread far beyond its disks (a tap amplitude of 1e9,
// an initial fraction of 1e-9): it would take gigabytes, or overflow the cells' indices.
constexpr double kMostCells = 1 << 28;

void DiskGrid::reset(double width, double height, double cell, double margin) {
  const double inv_cell = 1.0 / cell;
  // Counted in doubles first: an int would overflow before the check.
  const double cols = std::floor(width * inv_cell) + 1, rows = std::floor(height * inv_cell) + 1;
  const double pad = std::ceil(margin * inv_cell) + 1;
  if (!((cols + 2 * pad) * (rows + 2 * pad) <= kMostCells)) {
    std::ostringstream s;
    s << "expected a packing that a grid of at most 2^28 cells of side " << cell
      << " covers, got one of width " << width << " and height " << height
      << ": spread too thin for disks of these sizes";
    throw SpreadTooThin(s.str());
  }
  width_ = width;
  height_ = height;
  cell_ = cell;
  inv_cell_ = inv_cell;
  ncol_ = static_cast<int>(cols);
  nrow_ = static_cast<int>(rows);
  pad_ = static_cast<int>(pad);
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
