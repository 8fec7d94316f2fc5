#pragma once
// A pipeline's "sweep" section expanded into one assignment per point.
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "param_validation.hpp"

namespace granpipe {

// Far more points than a study runs, few enough that their pipelines (a few KB each)
// fit in memory.
inline constexpr std::size_t kMaxSweepPoints = 100000;

// Each point as {path: value}: grid = cartesian product, zip = element-wise. `paths`
// gets the swept parameter paths. More than kMaxSweepPoints points are refused before
// any is made.
std::vector<nlohmann::json> expand_sweep(const nlohmann::json& sweep, const JsonLocation& at,
                                         std::vector<std::string>& paths);

}  // namespace granpipe
