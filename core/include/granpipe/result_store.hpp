#pragma once
// results.h5 and its CSV copies. Written once at the end of a run, atomically
// (temporary name, flush, rename).
#include <filesystem>
#include <map>
#include <string>

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
};

// One results group per named producer (a sweep point's source and analyzers).
using ResultSet = std::map<std::string, Results>;

// Writes `dir/results.h5` and one CSV per table, histogram and scalar group beside it.
void write_results(const std::filesystem::path& dir, const ResultSet& results,
                   const Provenance& provenance);

}  // namespace granpipe
