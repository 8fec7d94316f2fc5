#include "granpipe/step_count.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

void check_step_count(double count, const std::string& what, const std::string& noun,
                      const std::string& how) {
  // Below, not up to: a count of 2^53 + 1 is 2^53 in a double, and was let through.
  if (count < kMostSteps) return;
  throw InputError(what + ": expected fewer than " + format_number(kMostSteps, 16) + " " + noun +
                   ", got " + format_number(count) + " (" + how + ")");
}

}  // namespace granpipe
