#pragma once
// A packing to continue tapping from: a frame of an H5MD file (a granpipe frames.h5 of
// this source, or another tool's spheres), checked against the box the pipeline asks for.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "granpipe/start_frame.hpp"
#include "tap_box.hpp"

namespace granpipe::spheres3d_tap {

struct SavedPacking {
  std::vector<Eigen::Vector3d> centres;
  std::int64_t step = 0;            // the frame's step: its tap, in a file of this source
  std::optional<std::int64_t> tap;  // its tap observable (a file of this source has one)
  std::string at;                   // "<where>: <file>: frame <k>", for messages
  std::optional<double> epsilon;    // the dilation its tap was made with, where the file says
  std::optional<std::int64_t> leg;  // its ramp leg (-1: a constant protocol), likewise
};

// The centres of a start frame. Throws InputError beginning with `start.where` when the
// frame is not 3D, holds other than `n` spheres, other radii than the box's, another box,
// spheres that overlap (by more than 1e-9 R) or reach through the bottom or a wall, or one
// higher than a column of all n could stand.
SavedPacking read_saved_packing(const StartFrame& start, const TapBox& box, long n);

}  // namespace granpipe::spheres3d_tap
