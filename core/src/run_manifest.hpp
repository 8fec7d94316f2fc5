#pragma once
// What a run wrote into its output directory. --overwrite removes these entries and
// nothing else: the run marker proves granpipe made the folder, not that a user added
// nothing to it since (notes.txt, a folder of plots), and those must survive a rerun.
#include <filesystem>
#include <string>
#include <vector>

namespace granpipe {

inline constexpr const char* kRunManifestName = ".granpipe-manifest";

// Writes the manifest of `dir`, listing the entries below it now that are named as a run
// names what it writes: its own files (the marker, pipeline.json, run.log, the results and
// frames files, sweep.*.csv) and point_NNN folders, and, in the folder or a point_NNN
// folder, files whose names start with one of `stages` (the source's "source", the
// analyzers' and writers' names), with a point_NNN. before it or not, and '.' or '_' after
// it. A user may add files while the run goes (notes.txt, a folder of plots): those are
// left out, and so protected. Names are relative, a directory's ends in '/'; a name
// holding a newline is left out too. granpipe's scripts add what they write into a
// finished run (report.html, pooled tables: scripts/run_manifest.py). Throws InputError.
void write_run_manifest(const std::filesystem::path& dir, const std::vector<std::string>& stages);

// The entries below `dir`, sorted, that its run did not write: those missing from its
// manifest, or, for a run without one (killed outright, or made before manifests), those
// that are not among the files a run writes before it ends (the marker, pipeline.json,
// run.log, the partial files and granpipe's report, in the folder or a point_NNN folder).
// A symlink is an entry of its own, never followed.
std::vector<std::string> foreign_entries(const std::filesystem::path& dir);

// Removes the entries of `dir` its run wrote, deepest first, then `dir` if nothing is
// left, and returns the foreign entries, left in place. Never follows a symlink.
std::vector<std::string> remove_run_entries(const std::filesystem::path& dir);

// "notes.txt, plots/" or, past `shown` entries, "a, b, c and 4 more".
std::string list_entries(const std::vector<std::string>& entries, std::size_t shown = 5);

}  // namespace granpipe
