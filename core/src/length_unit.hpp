#pragma once
// H5MD unit strings of lengths, as other tools write them: "nm", "angstrom", "Angstrom",
// "A", "10 nm" (H5MD allows a leading factor). One length written two ways is one unit.
#include <optional>
#include <string_view>

namespace granpipe {

// The length in metres that `unit` names, or nullopt where it is not a length this reader
// knows: an optional leading number ("10 nm", "10nm", "+2 nm"), then m with an SI prefix
// (k, c, m, u, µ or μ, n, p, f) or an angstrom (A, Å, angstrom, Angstrom), in UTF-8.
std::optional<double> metres_of(std::string_view unit);

// Whether two unit strings name one length: equal as text, or as metres within rounding.
bool same_length_unit(std::string_view a, std::string_view b);

}  // namespace granpipe
