#pragma once
// The number of steps a run counts (taps, time steps, cooling levels). Counts are 64-bit
// integers, and a count made of parameters (taps per step times steps times cycles, a
// duration over dt) wrapped round where it passed 2^63: 2^63 - 1 production taps counted
// -2^63 taps in all and ran none, exit 0 with every result NaN; a save_from of 1e16 with
// dt 1e-5 saved from t = 0. So a count is computed in doubles and refused above 2^53,
// where doubles stop counting whole steps (centuries of computing at any rate): 2^53 itself
// is refused, since 2^53 + 1 rounds to it.
#include <string>

namespace granpipe {

inline constexpr double kMostSteps = 9007199254740992.0;  // 2^53

// Throws InputError when `count` is kMostSteps or more, or not a number:
// "<what>: expected fewer than 9007199254740992 <noun>, got <count> (<how>)", `what` naming
// the parameter to change, `how` what the count is made of ("equilibration_taps +
// production_taps").
void check_step_count(double count, const std::string& what, const std::string& noun,
                      const std::string& how);

}  // namespace granpipe
