#include "memory_check.hpp"

#include <cmath>

#include "granpipe/available_memory.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe::dem {

void check_memory(const std::string& what, double particles) {
  const double available = available_memory();
  const double needed = particles * kBytesPerParticle;
  // 0 is a limit reached, not an unknown: refused.
  if (std::isnan(available) || needed <= available) return;
  constexpr double kGB = 1e9;
  throw InputError(what + ": " + format_number(particles) + " spheres need about " +
                   format_number(needed / kGB, 3) + " GB (" +
                   format_number(kBytesPerParticle / 1e3, 2) +
                   " kB each), this machine (or the process's memory limit) has " +
                   format_number(available / kGB, 3) + " GB available: expected at most " +
                   format_number(std::floor(available / kBytesPerParticle), 3) + " spheres");
}

}  // namespace granpipe::dem
