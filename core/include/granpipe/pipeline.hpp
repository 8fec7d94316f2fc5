#pragma once
// A pipeline: one source, analyzers, outputs, a seed and optional sweeps, read from
// JSON and validated against the plugins' schemas before anything runs
// (docs/pipelines.md).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "granpipe/plugin.hpp"
#include "granpipe/result_store.hpp"

namespace granpipe {

struct RunOptions {
  std::optional<std::filesystem::path> out;  // overrides output.dir
  int threads = 0;                           // 0: all hardware threads
  bool overwrite = false;                    // replace an earlier run's output directory
  bool progress = true;
};

struct RunSummary {
  std::filesystem::path output_dir;
  ResultSet results;
  long frames = 0;
  double seconds = 0.0;
  // Seconds per stage (the source, each analyzer, each writer, the frames file), summed
  // over the points, as results.h5 records them.
  std::vector<std::string> stage_names;
  std::vector<double> stage_seconds;
};

class Pipeline {
 public:
  // Parses `file`, applies `sets` ("json.path=value", value parsed as JSON or else taken
  // as a string), fills defaults and validates everything. Throws InputError.
  static Pipeline load(const std::filesystem::path& file, const std::vector<std::string>& sets,
                       const Registry& registry);
  // The same from JSON text; `origin` names it in error messages.
  static Pipeline parse(const std::string& text, const std::string& origin,
                        const std::vector<std::string>& sets, const Registry& registry);
  ~Pipeline();
  Pipeline(Pipeline&&) noexcept;
  Pipeline& operator=(Pipeline&&) noexcept;

  // The pipeline as it will run: defaults filled in, sweeps listed.
  std::string resolved_json() const;
  std::size_t points() const;
  std::uint64_t seed() const;

  // Instantiates every plugin of every point (catching cross-parameter errors and
  // source/analyzer mismatches) without running anything.
  void check(Log& log) const;
  // Runs into the output directory (docs/pipelines.md, "Output directory"): refused with
  // an InputError when unsafe or taken, replaced all at once with `overwrite`. While it
  // runs, SIGINT and SIGTERM mark the directory interrupted before ending the process.
  RunSummary run(const RunOptions& options, Log& log) const;

  struct Impl;  // opaque: defined inside the core library

 private:
  explicit Pipeline(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace granpipe
