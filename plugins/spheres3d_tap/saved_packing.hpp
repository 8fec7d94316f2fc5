#pragma once
// A packing to continue tapping from: a frame of an H5MD file (a granpipe frames.h5 of
// this source, or another tool's spheres), checked against the box the pipeline asks for.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

struct SavedPacking {
  std::vector<Eigen::Vector3d> centres;
  std::int64_t step = 0;            // the frame's step: its tap, in a file of this source
  std::optional<std::int64_t> tap;  // its tap observable (a file of this source has one)
  std::string at;                   // "<where>: <file>, frame <k>", for messages
};

// The centres of frame `frame` (-1: the last) of `file`. Throws InputError naming
// `frame_where` (that parameter) when the file has no such frame, and `where` (the file's
// parameter) and the file when the frame is not 3D, holds other than
// `n` spheres, other radii than the box's, another box, or spheres that overlap (by more
// than 1e-9 R) or reach through the bottom or a wall.
SavedPacking read_saved_packing(const std::string& where, const std::string& file,
                                const std::string& frame_where, long frame, const TapBox& box,
                                long n);

}  // namespace granpipe::spheres3d_tap
