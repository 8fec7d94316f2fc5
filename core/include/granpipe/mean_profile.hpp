#pragma once
// Mean over frames of profiles whose length varies from frame to frame (a profile up to the
// surface, which moves): a frame shorter than the longest counts zeros above its end, so
// that every bin's mean is over every frame.
#include <vector>

#include "granpipe/results.hpp"

namespace granpipe {

class MeanProfile {
 public:
  void add(const std::vector<double>& profile);
  const std::vector<RunningMean>& bins() const { return bins_; }

 private:
  std::vector<RunningMean> bins_;
  long frames_ = 0;
};

}  // namespace granpipe
