#pragma once
// Where a point's time goes: seconds spent in each stage of the pipeline (the source, each
// analyzer, each writer, the frames file), for the run's provenance. A few clock reads per
// frame cost tens of nanoseconds against a frame's microseconds at least.
#include <chrono>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace granpipe {

class StageClock {
 public:
  explicit StageClock(std::size_t stages) : seconds_(stages, 0.0) {}

  // Runs step() and adds its duration to `stage`; returns what step returns.
  template <class Step>
  decltype(auto) time(std::size_t stage, Step&& step) {
    const auto start = std::chrono::steady_clock::now();
    if constexpr (std::is_void_v<decltype(step())>) {
      step();
      add(stage, start);
    } else {
      decltype(auto) result = step();
      add(stage, start);
      return result;
    }
  }

  const std::vector<double>& seconds() const { return seconds_; }

 private:
  void add(std::size_t stage, std::chrono::steady_clock::time_point start) {
    seconds_[stage] +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  std::vector<double> seconds_;
};

}  // namespace granpipe
