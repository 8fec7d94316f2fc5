#include "granpipe/bin_count.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

void check_bin_count(double extent, double step, const std::string& what, const std::string& noun,
                     double most) {
  const double bins = extent / step;
  if (bins <= most) return;
  // Digits enough to tell the count from the limit (1.0000002e7 read "1e+07" against 1e7).
  throw InputError(what + ": expected at most " + format_number(most, 15) + " " + noun + ", got " +
                   format_apart(bins, most) + " (" + format_number(extent) + " in steps of " +
                   format_number(step, 15) + ")");
}

void check_step_fits(double extent, double step, const std::string& what,
                     const std::string& extent_name) {
  if (step <= extent * (1.0 + 1e-9)) return;
  throw InputError(what + ": expected at most " + extent_name + " (" + format_number(extent) +
                   "), got " + format_number(step) + ": a single bin would reach past it");
}

}  // namespace granpipe
