#pragma once
// The frames a file holds come in time: each defined time at or after the last defined one.
// An undefined time (NaN: a dump without ITEM: TIME or a timestep) is compared with nothing
// and not kept, so the frames around it are still compared with each other.
#include <cmath>
#include <limits>

namespace granpipe {

class TimeOrder {
 public:
  // True when `time` lies before the last defined time passed.
  bool runs_back(double time) const { return time < last_; }
  void pass(double time) {
    if (!std::isnan(time)) last_ = time;
  }
  double last() const { return last_; }

 private:
  double last_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace granpipe
