#include "run_manifest.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <string_view>

#include "granpipe/atomic_file.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/output_files.hpp"
#include "run_marker.hpp"

namespace granpipe {
namespace fs = std::filesystem;

namespace {

constexpr const char* kHeader = "# granpipe run manifest: what the run wrote here";
// scripts/report.py puts it into every report it writes.
constexpr const char* kReportMark = "<meta name=generator content=\"granpipe report\">";

struct Entry {
  std::string name;  // relative to the run's folder; a directory's ends in '/'
  fs::path path;
  bool directory = false;
};

// Every entry below `dir` by name, so each directory comes right before what it holds;
// symlinks not followed.
std::vector<Entry> entries_below(const fs::path& dir) {
  std::vector<Entry> entries;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code kind;
    const bool folder = it->symlink_status(kind).type() == fs::file_type::directory;
    const std::string name = it->path().lexically_relative(dir).generic_string();
    entries.push_back({folder ? name + "/" : name, it->path(), folder});
  }
  if (ec) throw InputError(dir.string() + ": cannot read the run's folder: " + ec.message());
  std::sort(entries.begin(), entries.end(),
            [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return entries;
}

std::optional<std::set<std::string>> read_manifest(const fs::path& dir) {
  const fs::path file = dir / kRunManifestName;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(file, ec))) return std::nullopt;
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line) || line != kHeader)
    throw InputError(file.string() + ": expected granpipe's list of what the run wrote, got " +
                     "another file; nothing was changed");
  std::set<std::string> names;
  while (std::getline(in, line)) names.insert(line);
  return names;
}

// The first `bytes` bytes of a file (fewer when it is shorter or unreadable).
std::string head_of(const fs::path& file, std::size_t bytes) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (!ec) bytes = static_cast<std::size_t>(std::min<std::uintmax_t>(bytes, size));
  std::ifstream in(file, std::ios::binary);
  std::string head(bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  return head;
}

// A regular file, not through a symlink: a FIFO named run.log hung --overwrite's reading.
bool regular_file(const fs::path& file) {
  std::error_code ec;
  return fs::is_regular_file(fs::symlink_status(file, ec));
}

bool is_report(const fs::path& file) {
  return regular_file(file) && head_of(file, 4096).find(kReportMark) != std::string::npos;
}

}  // namespace

void remove_report_of_results_so_far(const fs::path& dir) {
  const fs::path report = dir / "report.html";
  std::error_code ignored;  // gone already: nothing to do
  if (is_report(report)) fs::remove(report, ignored);
}

namespace {

// Whether the file starts as `start` does, or with a piece of it (a disk that filled up
// left a log empty).
bool starts_as(const fs::path& file, std::string_view start) {
  return start.rfind(head_of(file, start.size()), 0) == 0;
}

// Whether a file named like one a run writes before it ends holds what granpipe writes
// there: without a manifest (a run killed) the name alone let --overwrite remove a user's
// notes saved as point_001/run.log, or a folder point_007 of their own holding one.
bool holds_what_a_run_writes(const fs::path& file) {
  if (!regular_file(file)) return false;
  const std::string name = file.filename().string();
  // Its provenance line; or what a run stopped or failed before writing it says, or an
  // older granpipe's first warning.
  if (name == "run.log") {
    for (const char* first : {"granpipe ", "interrupted by ", "failed: ", "warning: "})
      if (starts_as(file, first)) return true;
    return false;
  }
  if (name == "frames.partial.h5" || name == "results.partial.h5")
    return starts_as(file, std::string_view("\x89HDF\r\n\x1a\n", 8));
  if (name == "pipeline.json") {
    const auto j = nlohmann::json::parse(head_of(file, std::size_t{64} << 20), nullptr, false);
    return j.is_object() && j.contains("source") && j["source"].is_object() &&
           j["source"].contains("plugin");
  }
  if (name == "report.html") return is_report(file);
  return name == kRunMarkerName;  // read and checked as a marker already
}

const std::regex& point_folder() {
  static const std::regex point("point_[0-9]+");
  return point;
}

// The name of a file or folder, and the folder it is in ("" at the top), without a folder's
// trailing '/'.
fs::path bare_name(const Entry& e) {
  return fs::path(e.directory ? e.name.substr(0, e.name.size() - 1) : e.name);
}

// At the top or in a point_NNN folder; folders only point_NNN at the top.
bool where_a_run_writes(const Entry& e) {
  const fs::path name = bare_name(e);
  const std::string parent = name.parent_path().string();
  if (e.directory) return parent.empty() && std::regex_match(name.string(), point_folder());
  return parent.empty() || std::regex_match(parent, point_folder());
}

// What any run writes before it ends, where it writes it, by name (a report by its mark).
bool named_as_written_before_the_end(const Entry& e) {
  static const std::set<std::string> files{kRunMarkerName, "pipeline.json", "run.log",
                                           "frames.partial.h5", "results.partial.h5"};
  if (!where_a_run_writes(e)) return false;
  if (e.directory) return true;
  const fs::path name = bare_name(e);
  return files.count(name.filename().string()) > 0 || (name == "report.html" && is_report(e.path));
}

// For a run without a manifest: those, holding what a run writes there.
bool written_before_the_end(const Entry& e) {
  return named_as_written_before_the_end(e) && (e.directory || holds_what_a_run_writes(e.path));
}

// The core's own files, the point folders the run made, and what the run recorded as it
// made it (its results and frames files, the plugins' files: output_files.hpp): never a
// file merely named like them. The run knows what it wrote:
// its own run.log may start with its interruption (a signal before the provenance line).
bool written_by_this_run(const Entry& e, const fs::path& dir, const FileRecord& recorded) {
  if (!where_a_run_writes(e)) return false;
  // A point folder is the run's only when the run made it: point_007 put there while a run
  // of three points (or of none) went was listed, and --overwrite removed what it held.
  const fs::path name = bare_name(e);
  const fs::path folder = e.directory ? name : name.parent_path();
  if (!folder.empty() && !recorded.has(dir / folder)) return false;
  return named_as_written_before_the_end(e) || recorded.has(dir / e.name);
}

// The files whose content says whether granpipe wrote them (holds_what_a_run_writes).
bool content_tells(const Entry& e) {
  static const std::set<std::string> files{
      kRunMarkerName,      "pipeline.json",      "run.log",
      "frames.partial.h5", "results.partial.h5", "report.html"};
  return !e.directory && files.count(bare_name(e).filename().string()) > 0;
}

class RunEntries {
 public:
  explicit RunEntries(const fs::path& dir) : manifest_(read_manifest(dir)) {}
  // A manifest names only places a run writes: one edited by hand (keep/, keep/k.txt) is
  // not believed beyond them; nor is a listed name whose file is now another's (a user's
  // own report.html put where the run's was).
  bool written_by_the_run(const Entry& e) const {
    if (!manifest_) return written_before_the_end(e);
    return manifest_->count(e.name) > 0 && where_a_run_writes(e) &&
           (!content_tells(e) || holds_what_a_run_writes(e.path));
  }

 private:
  std::optional<std::set<std::string>> manifest_;
};

}  // namespace

void write_run_manifest(const fs::path& dir, const FileRecord& recorded) {
  std::string text = std::string(kHeader) + "\n" + kRunManifestName + "\n";
  for (const Entry& e : entries_below(dir))
    if (e.name.find('\n') == std::string::npos && e.name != kRunManifestName &&
        written_by_this_run(e, dir, recorded))
      text += e.name + "\n";
  write_file_atomically(dir / kRunManifestName, text);
}

std::vector<std::string> foreign_entries(const fs::path& dir) {
  const RunEntries run(dir);
  std::vector<std::string> foreign;
  for (const Entry& e : entries_below(dir)) {
    // What a foreign folder holds is foreign with it, and not listed again.
    const bool inside_listed =
        !foreign.empty() && foreign.back().back() == '/' && e.name.rfind(foreign.back(), 0) == 0;
    if (!inside_listed && !run.written_by_the_run(e)) foreign.push_back(e.name);
  }
  return foreign;
}

std::vector<std::string> remove_run_entries(const fs::path& dir) {
  const RunEntries run(dir);
  const std::vector<Entry> entries = entries_below(dir);
  std::vector<std::string> left;
  for (auto e = entries.rbegin(); e != entries.rend(); ++e) {
    std::error_code ec;
    if (!run.written_by_the_run(*e) || !fs::remove(e->path, ec)) left.push_back(e->name);
  }
  std::error_code ec;
  if (left.empty()) fs::remove(dir, ec);
  std::sort(left.begin(), left.end());
  return left;
}

std::string list_entries(const std::vector<std::string>& entries, std::size_t shown) {
  std::string text;
  for (std::size_t k = 0; k < entries.size() && k < shown; ++k)
    text += (k ? ", " : "") + entries[k];
  if (entries.size() > shown) text += " and " + std::to_string(entries.size() - shown) + " more";
  return text;
}

}  // namespace granpipe
