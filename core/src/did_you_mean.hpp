#pragma once
#include <string>
#include <vector>

namespace granpipe {

// " (did you mean \"x\"?)" for the closest candidate within a few edits, or "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace granpipe
