#pragma once
// The names a pipeline gives: the run's (the default output directory, the CSV header
// line) and its analyzers' (HDF5 groups, file names). Kept plain, so that no name can
// leave the output directory or add a line to a CSV file.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "param_validation.hpp"

namespace granpipe {

inline constexpr std::size_t kMaxNameLength = 100;

// The pipeline's "name", or the file name without `.json` if it has none: letters,
// digits, _, - and . (not first).
std::string read_pipeline_name(const nlohmann::json& root, const JsonLocation& top,
                               const std::string& origin);

// Refuses an analyzer name that is not a letter followed by letters, digits and _, or
// that is one of the runner's own groups (source, sweep, point_*).
void check_analyzer_name(const nlohmann::json& name, const JsonLocation& at);

}  // namespace granpipe
