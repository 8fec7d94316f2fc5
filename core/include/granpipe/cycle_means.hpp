#pragma once
// Per-frame quantities averaged separately for every (cycle, time) a run visits. Protocols
// that revisit a control value keep it in the frame: annealed tapping stores the amplitude
// A as the frame time and the ramp as the cycle, so the rising and falling branches of
// φ(A) (the 2D paper's Fig. 8) come out as separate rows. Memory grows with the number of
// distinct (cycle, time) pairs, not with the number of frames.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "granpipe/frame.hpp"
#include "granpipe/results.hpp"

namespace granpipe {

class CycleMeans {
 public:
  explicit CycleMeans(std::vector<std::string> quantities) : names_(std::move(quantities)) {}
  // Adds one frame's values (one per quantity); frames without a cycle (cycle < 0) are ignored.
  void add(const Frame& frame, const std::vector<double>& values);
  bool empty() const { return means_.empty(); }
  // Columns: cycle, time, frames, then each quantity and its standard error.
  Table table(const std::string& doc) const;

 private:
  std::vector<std::string> names_;
  std::map<std::pair<std::int64_t, double>, std::vector<RunningMean>> means_;
};

}  // namespace granpipe
