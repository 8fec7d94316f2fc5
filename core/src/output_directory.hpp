#pragma once
// The run's output directory: checked before anything is written, claimed atomically,
// replaced all at once, and marked with how its run ended (docs/pipelines.md, "Output
// directory").
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "directory_lock.hpp"
#include "granpipe/output_files.hpp"
#include "interruption_record.hpp"
#include "run_marker.hpp"

namespace granpipe {

class Log;

// A file the run reads, and where the pipeline names it ("p.json: source.params.file").
struct InputFile {
  std::string where;
  std::filesystem::path file;
};

class OutputDirectory {
 public:
  // Checks `dir` without changing anything. Throws InputError for what granpipe must not
  // write into or replace: a symlink or a file; the root, working or home directory or
  // one holding them; one holding an input file; a directory granpipe did not make; one
  // another run is writing into; an earlier run's output without `overwrite`, or one
  // holding entries its run did not write.
  OutputDirectory(const std::filesystem::path& dir, bool overwrite,
                  const std::vector<InputFile>& inputs);
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::filesystem::path& final_path() const { return final_; }
  // Where the run writes: final_path(), or a new directory beside it while the run
  // replaces an earlier one, which stays untouched until this run is complete.
  const std::filesystem::path& work_path() const { return work_; }

  // Where the run records the files it writes beside the core's own, for its manifest.
  FileRecord& files() { return files_; }

  // Makes work_path() this run's: of two runs claiming one directory, one wins and the
  // other gets an InputError. Marks it running; SIGINT and SIGTERM now mark it interrupted.
  void claim();
  // Lists what the run wrote (run_manifest.hpp), marks it complete and, when it replaces
  // an earlier run, swaps it into final_path() and removes what the earlier one wrote.
  // Throws InputError when the swap fails.
  void complete(Log& log);
  // Marks the run failed, with `error` in its run.log.
  void fail(const std::string& error) noexcept;

 private:
  void check_earlier_run(bool overwrite);
  void claim_in_place();
  void claim_beside();
  std::filesystem::path swap_in();
  void remove_earlier(const std::filesystem::path& dir, Log& log);

  FileRecord files_;
  std::filesystem::path final_, work_;
  bool replacing_ = false, claimed_ = false, manifest_written_ = false;
  RunMarker marker_;
  std::string earlier_run_id_;
  std::optional<DirectoryLock> earlier_lock_, own_lock_;
  std::unique_ptr<InterruptionRecord> interruption_;
};

}  // namespace granpipe
