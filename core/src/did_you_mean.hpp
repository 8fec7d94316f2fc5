#pragma once
#include <string>
#include <vector>

namespace granpipe {

// " (did you mean \"x\"?)" for the closest candidate within a few edits, or "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

// "; known: a, b, c" (or "; known: " + `if_none`), the tail of an unknown-name message.
std::string known_list(const std::vector<std::string>& names, const std::string& if_none = "none");

}  // namespace granpipe
