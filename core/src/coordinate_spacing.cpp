#include "granpipe/coordinate_spacing.hpp"

#include <sstream>

#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"

namespace granpipe {

void require_fine_positions(double farthest, double allowance, double length,
                            const std::string& length_name, const std::string& where) {
  const double rounding = double_spacing(farthest);
  if (!(allowance * rounding > kFinestResolved * length)) return;
  std::ostringstream s;
  s << where << ": positions up to " << format_number(farthest)
    << " from the origin are rounded to " << format_number(rounding) << ": expected "
    << format_number(allowance) << " times that (" << format_number(allowance * rounding)
    << ") to be at most " << format_number(kFinestResolved) << " of the " << length_name << " ("
    << format_number(kFinestResolved * length) << "); move the origin into the packing";
  throw InputError(s.str());
}

}  // namespace granpipe
