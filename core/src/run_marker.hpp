#pragma once
// The marker granpipe writes into every output directory it makes. Only a directory
// with a marker may be replaced by --overwrite; the marker also tells how its run ended.
#include <filesystem>
#include <optional>
#include <string>

namespace granpipe {

inline constexpr const char* kRunMarkerName = ".granpipe-run";
inline constexpr std::size_t kRunMarkerSize = 192;  // bytes, whatever the status

enum class RunStatus { Running, Complete, Failed, Interrupted };
const char* to_string(RunStatus s);

struct RunMarker {
  std::string run_id;
  long pid = 0;
  std::string started;  // UTC, ISO 8601
  RunStatus status = RunStatus::Running;
};

// A new marker for this process's run, status Running.
RunMarker new_run_marker();

// The marker of `dir`, or nothing when it has none (a symlink is none). Throws
// InputError when the marker cannot be read as one.
std::optional<RunMarker> read_run_marker(const std::filesystem::path& dir);

// The marker's bytes: JSON padded to kRunMarkerSize.
std::string run_marker_text(const RunMarker& marker);

// Writes the marker of `dir`. Throws InputError.
void write_run_marker(const std::filesystem::path& dir, const RunMarker& marker);

}  // namespace granpipe
