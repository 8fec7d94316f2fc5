#pragma once
// Paths into a pipeline's JSON as users write them: "analyzers[0].params.scale".
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace granpipe {

// "a.b[2].c" -> {"a", "b", "2", "c"}: keys, and list indices as digit strings. Refuses
// (naming `where`) a malformed path or one of more than kMaxJsonDepth parts.
std::vector<std::string> split_path(const std::string& path, const std::string& where);

// The parts again as one path, as JsonLocation paths read.
std::string join_path(const std::vector<std::string>& parts);

// The value at `parts`, made (as null) if its object lacks the last keys; list entries
// must exist.
nlohmann::json& locate(nlohmann::json& root, const std::vector<std::string>& parts,
                       const std::string& where);

// Whether `path` is source.params.NAME or analyzers[K].params.NAME, or a path into such a
// parameter's value (source.params.walls.base.mu).
bool is_plugin_param_path(const std::string& path);

}  // namespace granpipe
