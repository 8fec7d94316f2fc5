#pragma once
// Which taps a run saves: every k-th, and optionally taps spaced evenly in log(tap)
// (about ten per decade), for the logarithmic compaction curves of the paper's Fig. 2.
#include <cstdint>

namespace granpipe::spheres3d_tap {

struct SaveSchedule {
  std::int64_t every = 10;
  bool logarithmic = true;
  bool start = true;  // tap 0, the deposition or the saved packing

  bool saves(std::int64_t tap) const;
};

}  // namespace granpipe::spheres3d_tap
