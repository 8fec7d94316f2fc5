#pragma once
// Numbers in messages and parameter descriptions, written the same way everywhere.
#include <string>

namespace granpipe {

// `x` as printf's %g with `digits` significant digits: 0.1, 1e-09, 12345.7 (6 digits);
// "nan", "inf" and "-inf" as such.
std::string format_number(double x, int digits = 6);

// `x` with as many digits (6 to 17) as it takes to tell it from `other`: in a message that
// compares the two, "expected at most 10, got 10" says nothing.
std::string format_apart(double x, double other);

// A point or vector of any length (an Eigen vector or row, a std::vector) as "(x, y, z)",
// each coordinate as format_number writes it: one look for positions in every message.
template <class Vector>
std::string format_point(const Vector& x, int digits = 6) {
  std::string s = "(";
  for (decltype(x.size()) k = 0; k < x.size(); ++k) {
    if (k > 0) s += ", ";
    s += format_number(x[k], digits);
  }
  s += ")";
  return s;
}

}  // namespace granpipe
