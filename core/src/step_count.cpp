#include "granpipe/step_count.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

void check_step_count(double count, const std::string& what, const std::string& noun,
                      const std::string& how) {
  if (count <= kMostSteps) return;
  throw InputError(what + ": expected at most " + format_number(kMostSteps, 16) + " " + noun +
                   ", got " + format_number(count) + " (" + how + ")");
}

}  // namespace granpipe
