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
  void finish();
  void set_enabled(bool on) { enabled_ = on; }
  double done() const { return done_.load(); }

 private:
  void print(bool final_line);
  std::string label_, unit_;
  double total_ = 0;
  std::atomic<double> done_{0.0};
  bool enabled_ = true;
  bool terminal_ = false;
  std::chrono::steady_clock::time_point start_;
  // Read by every advancing thread without the lock: an atomic count of nanoseconds.
  std::atomic<std::int64_t> last_print_ns_{0};
  std::mutex mutex_;
};

}  // namespace granpipe
