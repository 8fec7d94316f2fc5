#include "interruption_record.hpp"

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdint>

#include "run_marker.hpp"

namespace granpipe {
namespace {

constexpr int kSignals[] = {SIGINT, SIGTERM};

struct Prepared {
  int log_fd = -1;
  std::string marker_path, marker_text;
  std::string log_line[2], stderr_line[2];  // per entry of kSignals
  struct sigaction previous[2]{};
  bool handled[2] = {false, false};
};

std::atomic<bool> taken{false};           // by a live InterruptionRecord
std::atomic<Prepared*> armed{nullptr};    // set once everything is prepared
std::atomic<int> requested{0};            // the signal that asked the run to stop
std::atomic<int> claimed{0};              // the signal whose delivery records it
std::atomic<std::int64_t> claimed_at{0};  // when, in ns of CLOCK_MONOTONIC (0: being claimed)
// Only lock-free atomics may be touched in a signal handler.
static_assert(std::atomic<int>::is_always_lock_free &&
              std::atomic<std::int64_t>::is_always_lock_free);
Prepared prepared;

// A signal within this time of the first is the same request sent twice: timeout(1) sends
// SIGTERM to the run and then to its process group, and as a second signal it ended the run
// at once, its partial files left open for writing (h5py could not open them).
constexpr std::int64_t kSameRequestNs = 500'000'000;

std::int64_t monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe
  return std::int64_t{t.tv_sec} * 1'000'000'000 + t.tv_nsec;
}

void write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = write(fd, p, left);
    if (n <= 0) return;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
}

extern "C" void record_and_request_stop(int sig) {
  const int k = sig == SIGINT ? 0 : 1;
  const std::int64_t now = monotonic_ns();
  const Prepared* p = armed.load();
  if (!p) {
    // Nothing armed: the action from before, at once.
    sigaction(sig, &prepared.previous[k], nullptr);
    raise(sig);
    return;
  }
  // One delivery claims the request, whichever thread the kernel gives it to (a signal sent
  // to the process may land on any of the run's threads, a second one while the first is
  // still in here).
  int none = 0;
  if (!claimed.compare_exchange_strong(none, sig)) {
    const std::int64_t at = claimed_at.load();
    if (at == 0 || now - at < kSameRequestNs) return;  // the same request, sent again
    // A second request: the action from before (the default: end at once).
    sigaction(sig, &prepared.previous[k], nullptr);
    raise(sig);
    return;
  }
  claimed_at = now;
  write_all(p->log_fd, p->log_line[k]);
  // Markers all have one size: the new status overwrites the old in place.
  const int fd = open(p->marker_path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd >= 0) {
    write_all(fd, p->marker_text);
    close(fd);
  }
  write_all(STDERR_FILENO, p->stderr_line[k]);
  requested = sig;
}

}  // namespace

InterruptionRecord::InterruptionRecord(const std::filesystem::path& dir, std::string marker_text,
                                       const std::string& outcome) {
  if (taken.exchange(true)) return;
  const std::filesystem::path log = dir / "run.log";
  prepared.log_fd = open(log.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  prepared.marker_path = (dir / kRunMarkerName).string();
  prepared.marker_text = std::move(marker_text);
  for (int k = 0; k < 2; ++k) {
    const std::string name = kSignals[k] == SIGINT ? "SIGINT" : "SIGTERM";
    prepared.log_line[k] = "interrupted by " + name + " before the run finished\n";
    prepared.stderr_line[k] = "granpipe: interrupted by " + name + "; " + outcome + "\n";
  }
  requested = 0;
  claimed = 0;
  claimed_at = 0;
  armed = &prepared;
  armed_ = true;
  struct sigaction action {};
  action.sa_handler = record_and_request_stop;
  sigfillset(&action.sa_mask);
  for (int k = 0; k < 2; ++k) {
    sigaction(kSignals[k], nullptr, &prepared.previous[k]);
    // A signal the caller ignores (a background job's SIGINT) stays ignored.
    prepared.handled[k] = prepared.previous[k].sa_handler != SIG_IGN;
    if (prepared.handled[k]) sigaction(kSignals[k], &action, nullptr);
  }
}

InterruptionRecord::~InterruptionRecord() {
  if (!armed_) return;
  for (int k = 0; k < 2; ++k)
    if (prepared.handled[k]) sigaction(kSignals[k], &prepared.previous[k], nullptr);
  armed = nullptr;
  if (prepared.log_fd >= 0) close(prepared.log_fd);
  prepared.log_fd = -1;
  taken = false;
}

void throw_if_stop_requested() {
  if (const int sig = requested.load()) throw StopRequested{sig};
}

void end_by_signal(int signal) {
  // The record, disarmed, gave the signal back its earlier action.
  raise(signal);
}

}  // namespace granpipe
