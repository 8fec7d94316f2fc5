#pragma once
// Numbers in messages and parameter descriptions, written the same way everywhere.
#include <string>

namespace granpipe {

// `x` as printf's %g with `digits` significant digits: 0.1, 1e-09, 12345.7 (6 digits);
// "nan", "inf" and "-inf" as such.
std::string format_number(double x, int digits = 6);

}  // namespace granpipe
