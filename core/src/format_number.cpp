#include "granpipe/format_number.hpp"

#include <cstdio>

namespace granpipe {

std::string format_number(double x, int digits) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

}  // namespace granpipe
