#include "granpipe/available_memory.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace granpipe {

namespace {

// MemAvailable of /proc/meminfo, in bytes; infinity when unknown (the limits then decide).
double machine_available() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key;
    double kilobytes = 0.0;
    if (fields >> key >> kilobytes && key == "MemAvailable:") return kilobytes * 1024.0;
  }
  return std::numeric_limits<double>::infinity();
}

// What the process's address-space limit (ulimit -v, prlimit --as) leaves of it, in bytes;
// infinity without a limit.
double address_space_left() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY)
    return std::numeric_limits<double>::infinity();
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  statm >> pages;  // the process's size now
  return std::max(0.0, static_cast<double>(limit.rlim_cur) -
                           pages * static_cast<double>(sysconf(_SC_PAGESIZE)));
}

// The cgroup's page cache it can drop (a job that wrote large files sits near its limit).
double reclaimable(const std::string& dir) {
  std::ifstream stat(dir + "/memory.stat");
  std::string key;
  double bytes = 0.0;
  while (stat >> key >> bytes)
    if (key == "inactive_file") return bytes;
  return 0.0;
}

// What the process's cgroup (v2) memory limit leaves, in bytes; infinity without one.
double cgroup_left() {
  std::ifstream membership("/proc/self/cgroup");
  std::string line, group;
  while (std::getline(membership, line))
    if (line.rfind("0::", 0) == 0) group = line.substr(3);
  const std::string dir = "/sys/fs/cgroup" + group;
  std::ifstream max_file(dir + "/memory.max"), current_file(dir + "/memory.current");
  double max = 0.0, current = 0.0;
  if (!(max_file >> max) || !(current_file >> current))  // "max": no limit
    return std::numeric_limits<double>::infinity();
  return std::max(0.0, max - current + reclaimable(dir));
}

}  // namespace

double available_memory() {
  // A limit below the machine's free memory (a batch job's cgroup, prlimit --as 8 GB)
  // failed the run with std::bad_alloc after the check had passed it.
  const double least = std::min({machine_available(), address_space_left(), cgroup_left()});
  return std::isinf(least) ? std::numeric_limits<double>::quiet_NaN() : least;
}

}  // namespace granpipe
