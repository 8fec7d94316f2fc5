#pragma once
// How finely a dump's positions are printed, so that contacts found from them by distance
// (the analyzers' contact_tolerance, 1e-9 of the contact distance by default) can be
// judged. `dump custom` prints with %g unless told otherwise: six significant digits, so a
// centre at z = 12.3457 may be anywhere within 5e-5 of it, and two touching spheres of
// radius 0.5 may seem 1e-4 apart or overlapping by as much.
#include <array>
#include <climits>
#include <string_view>

namespace granpipe::lammps_dump {

// The digits of a number as written: "0.00149535" has 6 significant digits, the first of
// them at 10^-3; "1.2500000000000001e-02" 17, at 10^-2. Zero has none.
struct PrintedDigits {
  int significant = 0;
  int exponent = 0;  // power of ten of the first significant digit
};
PrintedDigits printed_digits(std::string_view word);
// Half a unit of the last digit written: how far the value the writer held may be from it.
double printed_rounding(std::string_view word);

// The most digits seen over a snapshot's positions and the largest magnitude per axis.
class PositionPrecision {
 public:
  void add(int axis, std::string_view word);
  // The largest rounding of a coordinate along each axis, half a unit of the last digit
  // printed at the largest magnitude, times `scale` (the box length for scaled positions).
  std::array<double, 3> rounding(const std::array<double, 3>& scale) const;
  int significant() const { return significant_; }

 private:
  int significant_ = 0;
  std::array<int, 3> exponent_{INT_MIN, INT_MIN, INT_MIN};
};

}  // namespace granpipe::lammps_dump
