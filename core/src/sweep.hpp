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

// The sweep's "seeds": "per_point" (the default: each point its own seeds, independent
// realizations) or "shared" (every point point 0's seeds, so that points differ only by
// their swept values: common random numbers for a resolution study). True for shared.
bool shared_sweep_seeds(const nlohmann::json& sweep, const JsonLocation& at);

}  // namespace granpipe
