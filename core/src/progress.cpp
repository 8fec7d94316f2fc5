#include "granpipe/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace granpipe {
namespace {
constexpr double kTerminalInterval = 0.2;  // seconds between bar redraws
constexpr double kLineInterval = 10.0;     // seconds between plain lines (logs, CI)

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  char buf[32];
  const long t = std::lround(s);
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%02ld:%02ld", t / 60, t % 60);
  return buf;
}
}  // namespace

void Progress::start(std::string label, double total, std::string unit) {
  std::lock_guard lock(mutex_);
  label_ = std::move(label);
  unit_ = std::move(unit);
  total_ = total;
  done_ = 0.0;
  skipped_ = 0.0;
  terminal_ = isatty(STDERR_FILENO) != 0;
  start_ = std::chrono::steady_clock::now();
  last_print_ns_ = start_.time_since_epoch().count();
}

void Progress::advance(double units) {
  double old = done_.load();
  while (!done_.compare_exchange_weak(old, old + units)) {
  }
  if (!enabled_) return;
  const std::int64_t now = std::chrono::steady_clock::now().time_since_epoch().count();
  const double interval = terminal_ ? kTerminalInterval : kLineInterval;
  const double since = static_cast<double>(now - last_print_ns_.load()) *
                       std::chrono::steady_clock::period::num /
                       std::chrono::steady_clock::period::den;
  if (since < interval) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // someone else is printing: skip, never wait
  last_print_ns_ = now;
  print("");
}

void Progress::skip(double units) {
  double old = skipped_.load();
  while (!skipped_.compare_exchange_weak(old, old + units)) {
  }
}

void Progress::set_status(std::string status) {
  std::lock_guard lock(mutex_);
  status_ = std::move(status);
}

void Progress::finish(bool completed) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  print(completed ? "done" : "stopped short");
}

void Progress::print(const char* final) {
  const bool final_line = *final != '\0';
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double advanced = done_.load();
  const double done = advanced + skipped_.load();
  const double rate = elapsed > 0 ? advanced / elapsed : 0.0;
  const double fraction = total_ > 0 ? std::min(1.0, done / total_) : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : NAN;
  const std::string status = status_.empty() ? "" : ", " + status_;
  if (terminal_) {
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    std::string bar(filled, '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r%s [%s] %5.1f%% %.0f/%.0f %s, %.3g %s/s, ETA %s%s   ", label_.c_str(),
                 bar.c_str(), 100 * fraction, done, total_, unit_.c_str(), rate, unit_.c_str(),
                 format_duration(eta).c_str(), status.c_str());
    if (final_line) std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "%s: %.0f/%.0f %s (%.1f%%), %.3g %s/s, elapsed %s, ETA %s%s\n",
                 label_.c_str(), done, total_, unit_.c_str(), 100 * fraction, rate, unit_.c_str(),
                 format_duration(elapsed).c_str(),
                 final_line ? final : format_duration(eta).c_str(), status.c_str());
  }
  std::fflush(stderr);
}

}  // namespace granpipe
