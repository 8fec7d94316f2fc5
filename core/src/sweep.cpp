#include "sweep.hpp"

#include <cstdio>

#include "granpipe/errors.hpp"
#include "json_path.hpp"

namespace granpipe {
using json = nlohmann::json;

namespace {

std::string read_mode(const json& sweep, const JsonLocation& at) {
  const bool mode_is_string = !sweep.contains("mode") || sweep["mode"].is_string();
  const std::string mode = mode_is_string ? sweep.value("mode", "grid") : "";
  if (mode != "grid" && mode != "zip") {
    throw InputError(at.child("mode").str() + ": expected one of \"grid\", \"zip\", got " +
                     json_brief(sweep["mode"]));
  }
  return mode;
}

// Two swept paths of which one holds the other (cells and cells[0]) would set one value
// twice at every point, the row recording both and the run using one.
void refuse_overlap(const std::vector<std::string>& paths, const std::string& path,
                    const JsonLocation& pat) {
  for (const std::string& earlier : paths) {
    if (!covers(earlier, path) && !covers(path, earlier)) continue;
    throw InputError(pat.quoted_key(path).str() + ": expected a parameter no other swept path " +
                     "holds or is part of, got one overlapping \"" + earlier + "\"");
  }
}

// The lists of values, each checked, with their paths.
std::vector<const json*> read_lists(const json& sweep, const JsonLocation& pat,
                                    std::vector<std::string>& paths) {
  if (!sweep.contains("parameters") || !sweep["parameters"].is_object() ||
      sweep["parameters"].empty()) {
    throw InputError(pat.str() + ": expected an object of \"path\": [values...], got " +
                     (sweep.contains("parameters") ? json_brief(sweep["parameters"]) : "nothing"));
  }
  std::vector<const json*> lists;
  for (const auto& [path, values] : sweep["parameters"].items()) {
    const std::string at = pat.quoted_key(path).str();
    if (!values.is_array() || values.empty()) {
      throw InputError(at + ": expected a non-empty list of values, got " + json_brief(values));
    }
    if (!is_plugin_param_path(path)) {
      throw InputError(at +
                       ": expected a plugin parameter path like source.params.name or "
                       "analyzers[0].params.name, got " +
                       json_brief(path));
    }
    split_path(path, at);  // refuses a second spelling of an index ([00])
    refuse_overlap(paths, path, pat);
    paths.push_back(path);
    lists.push_back(&values);
  }
  return lists;
}

// Refuses a sweep of more than kMaxSweepPoints points from the lists' lengths alone.
void check_point_count(const std::vector<const json*>& lists, bool zip, const JsonLocation& pat) {
  double points = zip ? static_cast<double>(lists[0]->size()) : 1.0;
  std::string sizes;
  for (const json* list : lists) {
    if (!zip) points *= static_cast<double>(list->size());
    sizes += (sizes.empty() ? "" : " x ") + std::to_string(list->size());
  }
  if (points <= static_cast<double>(kMaxSweepPoints)) return;
  char count[32];
  std::snprintf(count, sizeof count, "%g", points);
  throw InputError(pat.str() + ": expected at most " + std::to_string(kMaxSweepPoints) +
                   " sweep points, got " + count + (zip ? " (zip of " : " (grid of ") + sizes +
                   " values)");
}

std::vector<json> zip_points(const std::vector<const json*>& lists,
                             const std::vector<std::string>& paths, const JsonLocation& pat) {
  for (std::size_t k = 1; k < lists.size(); ++k) {
    if (lists[k]->size() != lists[0]->size()) {
      throw InputError(pat.quoted_key(paths[k]).str() + ": expected " +
                       std::to_string(lists[0]->size()) + " values (zip mode), got " +
                       std::to_string(lists[k]->size()));
    }
  }
  check_point_count(lists, true, pat);
  std::vector<json> points;
  points.reserve(lists[0]->size());
  for (std::size_t i = 0; i < lists[0]->size(); ++i) {
    json p = json::object();
    for (std::size_t k = 0; k < lists.size(); ++k) p[paths[k]] = (*lists[k])[i];
    points.push_back(std::move(p));
  }
  return points;
}

std::vector<json> grid_points(const std::vector<const json*>& lists,
                              const std::vector<std::string>& paths, const JsonLocation& pat) {
  check_point_count(lists, false, pat);
  std::vector<json> points{json::object()};
  for (std::size_t k = 0; k < lists.size(); ++k) {
    std::vector<json> next;
    next.reserve(points.size() * lists[k]->size());
    for (const auto& p : points) {
      for (const auto& v : *lists[k]) {
        json q = p;
        q[paths[k]] = v;
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  return points;
}

}  // namespace

std::vector<json> expand_sweep(const json& sweep, const JsonLocation& at,
                               std::vector<std::string>& paths) {
  check_keys(sweep, {"mode", "parameters", "seeds"}, at);
  const std::string mode = read_mode(sweep, at);
  const JsonLocation pat = at.child("parameters");
  const std::vector<const json*> lists = read_lists(sweep, pat, paths);
  return mode == "zip" ? zip_points(lists, paths, pat) : grid_points(lists, paths, pat);
}

bool shared_sweep_seeds(const json& sweep, const JsonLocation& at) {
  const json seeds = sweep.value("seeds", json("per_point"));
  if (seeds != "per_point" && seeds != "shared") {
    throw InputError(at.child("seeds").str() + ": expected one of \"per_point\", \"shared\", got " +
                     json_brief(seeds));
  }
  return seeds == "shared";
}

}  // namespace granpipe
