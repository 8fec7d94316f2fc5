#include "granpipe/format_number.hpp"

#include <cstdio>

namespace granpipe {

std::string format_number(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string format_apart(double x, double other) {
  for (int digits = 6;; ++digits) {
    const std::string s = format_number(x, digits);
    if (x == other || s != format_number(other, digits) || digits == 17) return s;
  }
}

}  // namespace granpipe
