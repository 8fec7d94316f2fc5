#pragma once
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace granpipe {

// Progress of a run on stderr: a bar with rate and ETA on a terminal, plain lines
// every `line_interval` otherwise (logs, CI). Thread-safe; sweep points share one.
class Progress {
 public:
  Progress() = default;
  void start(std::string label, double total, std::string unit);
  void advance(double units = 1.0);
  // Work a run begins with already done (a run continued from a saved frame): shown as done
  // but left out of the rate, so that the ETA is that of what is left.
  void skip(double units);
  // The last line: "done" when the run completed (a source may end before its estimated
  // work, as a relaxed DEM bed does), "stopped short" when it failed or was interrupted.
  void finish(bool completed = true);
  // A line the bar shows after its own figures (a source's simulated time, say); kept
  // until replaced.
  void set_status(std::string status);
  void set_enabled(bool on) { enabled_ = on; }
  double done() const { return done_.load(); }

 private:
  // final: "" for a line during the run, else what the ETA's place says at the end.
  void print(const char* final);
  std::string label_, unit_, status_;
  double total_ = 0;
  std::atomic<double> done_{0.0};
  std::atomic<double> skipped_{0.0};
  bool enabled_ = true;
  bool terminal_ = false;
  std::chrono::steady_clock::time_point start_;
  // Read by every advancing thread without the lock: an atomic count of nanoseconds.
  std::atomic<std::int64_t> last_print_ns_{0};
  std::mutex mutex_;
};

}  // namespace granpipe
