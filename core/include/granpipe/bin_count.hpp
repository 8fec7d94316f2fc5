#pragma once
// The size of a histogram, profile or grid whose step is a parameter. A step given in the
// wrong unit, or mistyped, asks for more bins than memory holds or than an int counts (a
// count cast to int wrapped around to none or one bin: an empty profile or a one-cut
// "average", exit 0). Such a count is refused before anything is allocated.
#include <string>

namespace granpipe {

// The most bins (cuts, grid points) one histogram or profile may have.
inline constexpr double kMaxBins = 1e7;

// Throws InputError when `extent / step` is above `most` or not a number:
// "<what>: expected at most 10000000 <noun>, got <extent / step> (<extent> in steps of
// <step>)". `extent` and `step` in the parameter's unit, `what` names the parameter.
void check_bin_count(double extent, double step, const std::string& what,
                     const std::string& noun = "bins", double most = kMaxBins);

// Throws InputError when `step` is longer than `extent` (beyond rounding, a relative 1e-9),
// where a single bin would reach past what it measures (pores' histogram widened to its
// one bin past xi_max, a profile's one bin mostly above the bed, exit 0):
// "<what>: expected at most <extent_name> (<extent>), got <step>: ...".
void check_step_fits(double extent, double step, const std::string& what,
                     const std::string& extent_name);

}  // namespace granpipe
