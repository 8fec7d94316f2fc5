#pragma once
// Per-frame quantities of a ramped protocol averaged per branch and control value, for
// the analyzers that opt in. A ramped source (annealed tapping) stores two observables
// per frame: the control value (the amplitude A) and the half-cycle `cycle`: 0 the first
// increase, odd ones decreasing, even ones (from 2 on) increasing. The 2D paper's Fig. 8
// keeps the first increase apart and pools the later increasing and decreasing ramps,
// each over all its cycles: that is one row per (branch, control value) here. Memory
// grows with the distinct (branch, value) pairs, not with frames.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "granpipe/frame.hpp"
#include "granpipe/results.hpp"

namespace granpipe {

enum class RampBranch : std::int8_t { FirstIncrease = 0, Decreasing = 1, Increasing = 2 };
// The branch of a half-cycle index (cycle >= 0).
RampBranch ramp_branch(std::int64_t cycle);

class RampMeans {
 public:
  // The 3D tapping source names its observables `epsilon` and `leg`.
  explicit RampMeans(std::vector<std::string> quantities, std::string control = "amplitude",
                     std::string cycle = "cycle")
      : names_(std::move(quantities)), control_(std::move(control)), cycle_(std::move(cycle)) {}
  // Adds one frame's values (one per quantity); frames without a cycle and a control
  // value among their observables are ignored, and an undefined value (NaN) is left out of
  // its quantity's mean, as the scalar means leave it out (one thin frame made a whole
  // branch's row NaN).
  void add(const Frame& frame, const std::vector<double>& values);
  bool empty() const { return means_.empty(); }
  // Columns: branch (0 first increase, 1 decreasing, 2 increasing), the control value
  // (named after its observable), frames, then each quantity's mean over the frames where
  // it is defined (NaN where it is nowhere) and its standard error.
  Table table(const std::string& doc) const;

 private:
  struct Means {
    long frames = 0;
    std::vector<RunningMean> of;  // one per quantity
  };
  std::vector<std::string> names_;
  std::string control_, cycle_;
  std::map<std::pair<RampBranch, double>, Means> means_;
};

}  // namespace granpipe
