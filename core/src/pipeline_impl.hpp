#pragma once
// What a validated pipeline holds; shared by its parsing and its running.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "granpipe/pipeline.hpp"
#include "param_validation.hpp"

namespace granpipe {

struct PointSpec {
  nlohmann::json assignment;  // {"source.params.A": 1.1, ...}; empty without sweep
  nlohmann::json resolved;    // the whole pipeline of this point, defaults filled in
  Params source_params;
  std::vector<Params> analyzer_params, writer_params;
};

// " (sweep point k: path = value, ...)" after a message about point k of a sweep, so that
// the value at fault is named; "" without a sweep.
std::string sweep_point_note(const PointSpec& point, std::size_t k);

// An analyzer or writer of the pipeline.
struct PluginSpec {
  const PluginInfo* info = nullptr;
  std::string name;   // unique among the analyzers and writers
  std::string where;  // "file: analyzers[k]"
  // An analyzer's "publish": false keeps its columns out of the frames, so that a second
  // instance of a plugin can measure again without clashing with the first's columns.
  bool publish = true;
};

struct Pipeline::Impl {
  std::string origin;          // file name, for messages
  std::filesystem::path file;  // the pipeline file, when read from one
  std::filesystem::path base_dir;
  std::string name, description;
  std::uint64_t seed = 1;
  const PluginInfo* source = nullptr;
  std::vector<PluginSpec> analyzers, writers;
  std::filesystem::path output_dir;
  bool save_frames = true;
  std::int64_t frame_stride = 1;
  std::vector<std::string> sweep_paths;
  bool shared_seeds = false;        // every sweep point point 0's seeds (sweep "seeds": "shared")
  std::vector<Override> overrides;  // --set values, then the sweep's paths
  JsonLocation top() const { return {origin, "", &overrides}; }
  std::vector<PointSpec> points;
  nlohmann::json resolved;  // as run: point 0's values plus the sweep
};

}  // namespace granpipe
