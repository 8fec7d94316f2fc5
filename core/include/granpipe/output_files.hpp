#pragma once
// The files a plugin instance writes into the run's folder. Each name is recorded as the
// run's when it is made: the run's manifest lists what was so recorded beside the core's
// own files, and a later --overwrite removes that and nothing else. (The manifest once took
// every file named like a stage's for the run's: packing_notes.txt, dropped into the folder
// while the run went, was removed by the next --overwrite.)
#include <filesystem>
#include <mutex>
#include <set>
#include <string>

namespace granpipe {

// What the run wrote, recorded by its plugins' threads as they name their files.
class FileRecord {
 public:
  void add(const std::filesystem::path& file);
  bool has(const std::filesystem::path& file) const;

 private:
  mutable std::mutex mutex_;
  std::set<std::filesystem::path> files_;
};

// Names an instance's files: ctx.output_files().path(".xyz").
class OutputFiles {
 public:
  OutputFiles() = default;
  OutputFiles(FileRecord* record, std::filesystem::path dir, std::string name);
  // False when the run writes no files (a pipeline only checked, a test without a folder).
  bool enabled() const { return !dir_.empty(); }
  // <run folder>/<instance name><suffix>, recorded as the run's. `suffix` starts with '.'
  // or '_' and names no folder (".xyz", "_frame_000012.svg"); anything else is an
  // InternalError (a plugin's mistake, not the user's). Without a folder (a pipeline only
  // checked), the bare name, recorded nowhere: callable from a plugin's constructor.
  std::filesystem::path path(const std::string& suffix) const;

 private:
  FileRecord* record_ = nullptr;
  std::filesystem::path dir_;
  std::string name_;
};

}  // namespace granpipe
