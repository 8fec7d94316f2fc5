#pragma once
// A uniform grid of square cells small enough that no two non-overlapping disks can
// have their centres in one cell (side < smallest diameter / sqrt 2), so each cell holds
// one disk index or none: O(1) updates and flat-array queries, no lists. A margin of
// empty cells around the box lets queries run without bounds checks.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "granpipe/errors.hpp"

namespace granpipe::disks2d_tap {

// A packing spread too thin for the grid (reset): its callers put the parameter that
// spread it in front (initial_fraction, A).
class SpreadTooThin : public InputError {
 public:
  using InputError::InputError;
};

class DiskGrid {
 public:
  static constexpr std::int32_t kEmpty = -1;

  // Cells covering x in [0, width], y in [0, height], with `margin` (a distance) of
  // padding cells around them. Empties the grid. SpreadTooThin beyond 2^28 cells.
  void reset(double width, double height, double cell, double margin);

  double cell_size() const { return cell_; }
  double height() const { return height_; }
  int cell_of(double x, double y) const { return (row_of(y) + pad_) * stride_ + col_of(x) + pad_; }
  std::int32_t at(int cell) const { return cells_[static_cast<std::size_t>(cell)]; }
  // Puts disk i into `cell`; throws InternalError when another disk is there already
  // (which only overlapping disks can cause).
  void put(std::int32_t i, int cell);
  void erase(int cell) { cells_[static_cast<std::size_t>(cell)] = kEmpty; }
  // True when (x, y) lies in the covered area (margin excluded).
  bool covers(double x, double y) const {
    return x >= 0.0 && x <= width_ && y >= 0.0 && y <= height_;
  }

  // Calls f(j) for every disk whose centre lies in a cell touching [x0,x1] x [y0,y1].
  template <class F>
  void for_each_in(double x0, double x1, double y0, double y1, F&& f) const {
    const int c0 = std::max(col_of(x0), -pad_), c1 = std::min(col_of(x1), ncol_ + pad_ - 1);
    const int r0 = std::max(row_of(y0), -pad_), r1 = std::min(row_of(y1), nrow_ + pad_ - 1);
    for (int row = r0; row <= r1; ++row) {
      const std::int32_t* line = cells_.data() + (row + pad_) * stride_ + pad_;
      for (int col = c0; col <= c1; ++col) {
        const std::int32_t j = line[col];
        if (j != kEmpty) f(j);
      }
    }
  }

 private:
  // floor() without a library call (x86-64 baseline has no rounding instruction).
  static int floor_int(double v) {
    const int t = static_cast<int>(v);
    return t - (v < static_cast<double>(t));
  }
  int col_of(double x) const { return floor_int(x * inv_cell_); }
  int row_of(double y) const { return floor_int(y * inv_cell_); }

  double width_ = 0, height_ = 0, cell_ = 1, inv_cell_ = 1;
  int ncol_ = 0, nrow_ = 0, pad_ = 0, stride_ = 0;
  std::vector<std::int32_t> cells_;
};

}  // namespace granpipe::disks2d_tap
