#include "idle_cores.hpp"

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace granpipe::dem {

namespace {

int cores_allowed() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) != 0)
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return CPU_COUNT(&set);
}

// Runnable threads of the machine (the running one included), or -1.
int procs_running() {
  std::ifstream stat("/proc/stat");
  std::string key;
  int count = -1;
  while (stat >> key) {
    if (key == "procs_running") return (stat >> count) ? count : -1;
    stat.ignore(INT_MAX, '\n');
  }
  return -1;
}

// This process's threads in state R (the caller, and OpenMP threads still spinning).
int own_running_threads() {
  int running = 0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    std::ifstream stat(task.path() / "stat");
    std::string line;
    std::getline(stat, line);
    // "pid (comm) S ...": the state follows the last ')' (comm may hold one).
    const auto close = line.rfind(')');
    if (close != std::string::npos && close + 2 < line.size() && line[close + 2] == 'R') ++running;
  }
  return std::max(running, 1);
}

}  // namespace

int idle_cores() {
  const int cores = cores_allowed();
  // The fewest of a few samples: a process that runs for a moment is no competitor.
  int others = INT_MAX;
  for (int k = 0; k < 5 && others > 0; ++k) {
    if (k) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    const int all = procs_running();
    if (all < 0) return cores;
    others = std::min(others, std::max(all - own_running_threads(), 0));
  }
  return std::max(cores - others, 0);
}

}  // namespace granpipe::dem
