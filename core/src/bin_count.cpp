#include "granpipe/bin_count.hpp"

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

void check_bin_count(double extent, double step, const std::string& what, const std::string& noun,
                     double most) {
  const double bins = extent / step;
  if (bins <= most) return;
  throw InputError(what + ": expected at most " + format_number(most, 15) + " " + noun + ", got " +
                   format_number(bins) + " (" + format_number(extent) + " in steps of " +
                   format_number(step) + ")");
}

}  // namespace granpipe
