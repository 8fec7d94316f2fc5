#pragma once
// results.h5 and its CSV copies. Written once at the end of a run, atomically
// (temporary name, flush, rename).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "granpipe/output_files.hpp"
#include "granpipe/results.hpp"

namespace granpipe {

struct Provenance {
  std::string pipeline_name;
  std::string pipeline_json;  // the pipeline as run, defaults filled in
  std::string version, commit;
  std::uint64_t seed = 0;
  int threads = 1;
  double wall_seconds = 0.0;
  std::string started;  // ISO 8601 UTC
  bool complete = true;
  // Where the time went: the source, each analyzer, each writer and the frames file, in
  // pipeline order, summed over sweep points (which may run at once, so the sum can
  // exceed wall_seconds).
  std::vector<std::string> stage_names;
  std::vector<double> stage_seconds;
};

// "granpipe 0.1.0 commit 3f2a... pipeline tap2d seed 7": the run, as every file it writes
// names it (the CSV files' # line, the writers' files).
std::string run_label(const Provenance& p);

// One results group per named producer (a sweep point's source and analyzers).
using ResultSet = std::map<std::string, Results>;

// Writes `dir/results.h5` and one CSV per table, histogram and scalar group beside it,
// each recorded in `record` as the run's before it is made.
void write_results(const std::filesystem::path& dir, const ResultSet& results,
                   const Provenance& provenance, FileRecord& record);

}  // namespace granpipe
