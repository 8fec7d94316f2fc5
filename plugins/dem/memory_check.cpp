#include "memory_check.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::dem {

double available_memory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line)) {
    std::istringstream fields(line);
    std::string key;
    double kilobytes = 0.0;
    if (fields >> key >> kilobytes && key == "MemAvailable:") return kilobytes * 1024.0;
  }
  return 0.0;
}

void check_memory(const std::string& what, double particles) {
  const double available = available_memory();
  const double needed = particles * kBytesPerParticle;
  if (available <= 0.0 || needed <= available) return;
  constexpr double kGB = 1e9;
  throw InputError(what + ": " + format_number(particles) + " spheres need about " +
                   format_number(needed / kGB, 3) + " GB (" +
                   format_number(kBytesPerParticle / 1e3, 2) + " kB each), this machine has " +
                   format_number(available / kGB, 3) + " GB available: expected at most " +
                   format_number(std::floor(available / kBytesPerParticle), 3) + " spheres");
}

}  // namespace granpipe::dem
