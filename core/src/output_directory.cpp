#include "output_directory.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "granpipe/errors.hpp"
#include "granpipe/log.hpp"
#include "output_path_checks.hpp"
#include "run_manifest.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

std::string describe_earlier(const RunMarker& m) {
  switch (m.status) {
    case RunStatus::Complete:
      return "the output of an earlier run";
    case RunStatus::Failed:
      return "a failed run (its run.log says why)";
    case RunStatus::Interrupted:
      return "an interrupted run";
    case RunStatus::Running:
      return "a run that stopped before it finished (killed?)";
  }
  return "an earlier run";
}

// A sibling of `dir` for this run, named after it (its run id is unique).
fs::path beside(const fs::path& dir, const char* what, const RunMarker& run) {
  return dir.string() + ".granpipe-" + what + "-" + run.run_id;
}

bool is_empty_directory(const fs::path& dir) {
  std::error_code ec;
  const bool empty = fs::is_empty(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot read the output directory: " + ec.message());
  return empty;
}

// A directory itself, not a symbolic link to one.
bool is_real_directory(const fs::path& path) {
  std::error_code ec;
  return fs::symlink_status(path, ec).type() == fs::file_type::directory;
}

// The new run's folder takes the earlier one's permissions and owner: a folder the user had
// made private (0700) came back world-readable after --overwrite. An owner this process may
// not give (it is not root) stays the process's.
void keep_access_of(const fs::path& from, const fs::path& to) {
  struct stat earlier;
  if (stat(from.c_str(), &earlier) != 0) return;
  const int owner_given = chown(to.c_str(), earlier.st_uid, earlier.st_gid);
  chmod(to.c_str(), earlier.st_mode & 07777);  // after chown, which may clear set-id bits
  (void)owner_given;
}

void append_line(const fs::path& file, const std::string& line) {
  std::ofstream out(file, std::ios::app);
  out << line << '\n';
}

}  // namespace

OutputDirectory::OutputDirectory(const fs::path& dir, bool overwrite,
                                 const std::vector<InputFile>& inputs)
    : final_(without_trailing_separators(dir)), work_(final_), marker_(new_run_marker()) {
  check_output_spelling(final_);
  check_output_kind(final_);
  check_output_place(final_, inputs);
  std::error_code ec;
  if (fs::exists(final_, ec) && !is_empty_directory(final_)) check_earlier_run(overwrite);
}

// A run that failed or was interrupted lists what it wrote too, once its files are closed.
OutputDirectory::~OutputDirectory() {
  if (!claimed_ || manifest_written_) return;
  try {
    write_run_manifest(work_, files_);
  } catch (const InputError&) {
    // A full disk: without a manifest, --overwrite removes only what every run writes.
  }
}

// Every writer of a marker holds the directory's lock, so the marker is read under it.
void OutputDirectory::check_earlier_run(bool overwrite) {
  const std::string shown = final_.string();
  earlier_lock_ = DirectoryLock::try_lock(final_);
  if (!earlier_lock_) {
    throw InputError(shown +
                     ": another granpipe run is writing or replacing this output directory; wait "
                     "for it to end or choose another --out");
  }
  const std::optional<RunMarker> earlier = read_run_marker(final_);
  if (!earlier && !overwrite) {
    throw InputError(
        shown +
        ": expected a new or empty output directory, got a non-empty one that granpipe "
        "did not make; choose another --out");
  }
  if (!earlier) {
    const std::string hint =
        fs::exists(final_ / "pipeline.json")
            ? " (if an older granpipe, which wrote no marker, made it: remove it yourself)"
            : "";
    throw InputError(shown + ": --overwrite replaces only directories granpipe made (they hold a " +
                     kRunMarkerName + " file), got one without" + hint + "; nothing was changed");
  }
  if (!overwrite) {
    throw InputError(shown + ": expected a new or empty output directory, got one holding " +
                     describe_earlier(*earlier) +
                     "; pass --overwrite to replace it, or choose another --out");
  }
  const std::vector<std::string> foreign = foreign_entries(final_);
  if (!foreign.empty()) {
    std::error_code ec;
    const std::string unlisted =
        fs::exists(final_ / kRunManifestName, ec)
            ? ""
            : " (its run left no list of what it wrote: it was killed, or an older granpipe "
              "made it)";
    throw InputError(shown +
                     ": --overwrite removes only what granpipe wrote, and this run's folder " +
                     "also holds " + list_entries(foreign) + unlisted +
                     "; move them out or remove the folder yourself; nothing was changed");
  }
  check_removable(final_);
  earlier_run_id_ = earlier->run_id;
  replacing_ = true;
  work_ = beside(final_, "new", marker_);
}

void OutputDirectory::claim() {
  std::error_code ec;
  if (final_.has_parent_path()) fs::create_directories(final_.parent_path(), ec);
  if (ec)
    throw InputError(final_.string() + ": cannot create its parent directory: " + ec.message());
  if (replacing_)
    claim_beside();
  else
    claim_in_place();
  claimed_ = true;
  RunMarker interrupted = marker_;
  interrupted.status = RunStatus::Interrupted;
  const std::string outcome =
      replacing_ ? "the earlier run in " + final_.string() + " is untouched; this one is in " +
                       work_.string() + ", marked interrupted"
                 : final_.string() + " is marked interrupted (rerun with --overwrite)";
  interruption_ =
      std::make_unique<InterruptionRecord>(work_, run_marker_text(interrupted), outcome);
}

// A new or empty directory is claimed by its lock: a second run cannot take the lock,
// or takes it only after the first has written its marker.
void OutputDirectory::claim_in_place() {
  const bool made = mkdir(final_.c_str(), 0777) == 0;
  if (!made && errno != EEXIST)
    throw InputError(final_.string() +
                     ": cannot create the output directory: " + std::strerror(errno));
  check_output_kind(final_);  // a symlink made since the checks
  own_lock_ = DirectoryLock::try_lock(final_);
  if (!own_lock_ || !is_empty_directory(final_)) {
    own_lock_.reset();
    throw InputError(final_.string() +
                     ": another granpipe run has just claimed this output directory; "
                     "choose another --out");
  }
  try {
    write_run_marker(final_, marker_);
  } catch (const InputError&) {
    std::error_code ignored;
    fs::remove(final_ / kRunMarkerName, ignored);
    if (made) fs::remove(final_, ignored);  // ours, and empty again
    own_lock_.reset();
    throw;
  }
}

// A replacing run builds beside the earlier one, whose lock it holds since the checks.
void OutputDirectory::claim_beside() {
  if (mkdir(work_.c_str(), 0777) != 0) {
    throw InputError(final_.string() + ": cannot create the new run's directory " + work_.string() +
                     ": " + std::strerror(errno) + "; nothing was changed");
  }
  keep_access_of(final_, work_);
  own_lock_ = DirectoryLock::try_lock(work_);
  try {
    write_run_marker(work_, marker_);
  } catch (const InputError&) {
    std::error_code ignored;
    fs::remove_all(work_, ignored);  // ours, made just now
    own_lock_.reset();
    throw;
  }
}

void OutputDirectory::complete(Log& log) {
  interruption_.reset();
  throw_if_stop_requested();  // a signal that came before the handlers were given back
  remove_report_of_results_so_far(work_);
  write_run_manifest(work_, files_);
  manifest_written_ = true;
  marker_.status = RunStatus::Complete;
  write_run_marker(work_, marker_);
  if (replacing_) remove_earlier(swap_in(), log);
}

// Returns where the earlier run is now (nothing when it is gone).
fs::path OutputDirectory::swap_in() {
  const fs::path built = work_;
  auto refuse = [&](int why) {
    throw InputError(final_.string() + ": cannot swap the new run in (" + std::strerror(why) +
                     "); the earlier run is untouched and this one is in " + built.string());
  };
  if (renameat2(AT_FDCWD, built.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE) == 0) {
    // <out> made a symlink while the run went: the earlier run's files would be removed
    // through it, wherever it points. The exchange is undone and the link left to the user.
    if (!is_real_directory(built)) {
      renameat2(AT_FDCWD, built.c_str(), AT_FDCWD, final_.c_str(), RENAME_EXCHANGE);
      throw InputError(final_.string() +
                       ": expected the earlier run's folder, got something else put there "
                       "while this run went (a symbolic link?); it is left as it is and this "
                       "run is in " +
                       built.string());
    }
    work_ = final_;
    // What was in <out> now bears the new run's temporary name, which the docs say may be
    // deleted: what is left of it (a user's note, or a folder put there during the run)
    // goes by a name that says it was there before.
    const fs::path aside = beside(final_, "old", marker_);
    return std::rename(built.c_str(), aside.c_str()) == 0 ? aside : built;
  }
  // <out> removed while the run went (the message said "the earlier run is untouched"):
  // nothing to swap with, the new run takes its place.
  if (errno == ENOENT && std::rename(built.c_str(), final_.c_str()) == 0) {
    work_ = final_;
    return {};
  }
  if (errno != EINVAL && errno != ENOSYS) refuse(errno);
  // A file system without atomic exchange: two renames, the first undone if the second fails.
  if (!is_real_directory(final_)) refuse(ENOTDIR);
  const fs::path aside = beside(final_, "old", marker_);
  if (std::rename(final_.c_str(), aside.c_str()) != 0) refuse(errno);
  if (std::rename(built.c_str(), final_.c_str()) != 0) {
    const int second = errno;
    std::rename(aside.c_str(), final_.c_str());
    refuse(second);
  }
  work_ = final_;
  return aside;
}

void OutputDirectory::remove_earlier(const fs::path& dir, Log& log) {
  earlier_lock_.reset();
  if (dir.empty()) {
    log.warn(final_.string() + ": the earlier run was removed while this one went");
    return;
  }
  std::optional<RunMarker> earlier;
  try {
    earlier = read_run_marker(dir);
  } catch (const InputError&) {
  }
  if (!earlier || earlier->run_id != earlier_run_id_) {
    log.warn(dir.string() +
             ": expected the earlier run replaced by this one, got something else; "
             "left in place");
    return;
  }
  const std::vector<std::string> left = remove_run_entries(dir);
  if (!left.empty()) {
    log.warn(dir.string() + ": the earlier run's folder, left in place: it holds " +
             list_entries(left) + ", which the run did not write or could not be removed");
  }
}

void OutputDirectory::fail(const std::string& error) noexcept {
  if (!claimed_) return;
  interruption_.reset();
  try {
    append_line(work_ / "run.log", "failed: " + error);
    if (replacing_)
      append_line(work_ / "run.log", "the earlier run in " + final_.string() + " is untouched");
    marker_.status = RunStatus::Failed;
    write_run_marker(work_, marker_);
  } catch (...) {
    // A full disk may refuse these too; the error itself still reaches the user.
  }
}

}  // namespace granpipe
