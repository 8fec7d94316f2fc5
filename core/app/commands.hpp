#pragma once
#include <filesystem>
#include <string>

#include "granpipe/plugin.hpp"

namespace granpipe::app {

// `granpipe describe NAME`: the plugin's schema as documentation.
void describe(const Registry& registry, const std::string& name);
// `granpipe plugins`: every plugin found, and every library refused.
void list_plugins(const Registry& registry);
// `granpipe inspect FILE.h5`: frames, N, dim and what each frame holds.
void inspect(const std::string& path, long max_rows);

// report.html in a run's directory, made by the installed report script (python3 with
// h5py and matplotlib). A run goes on without it: a failure is a warning, not an error.
struct ReportOutcome {
  bool written = false;
  std::string why_not;  // one line when not written
  // The script refused the run directory (exit 2) and printed the one line that says why.
  bool refused = false;
};
ReportOutcome write_report(const std::filesystem::path& run_dir);

}  // namespace granpipe::app
