#pragma once
// What a run wrote into its output directory. --overwrite removes these entries and
// nothing else: the run marker proves granpipe made the folder, not that a user added
// nothing to it since (notes.txt, a folder of plots), and those must survive a rerun.
#include <filesystem>
#include <string>
#include <vector>

#include "granpipe/output_files.hpp"

namespace granpipe {

inline constexpr const char* kRunManifestName = ".granpipe-manifest";

// Writes the manifest of `dir`, listing the entries below it now that the run wrote: its
// own files (the marker, pipeline.json, run.log, the results and frames files, granpipe's
// report), the point_NNN folders, and the files `recorded` (the CSV tables, what plugins
// named with ctx.output_files()). A file a user adds while the run goes (notes.txt,
// packing_notes.txt, a folder of plots) is left out whatever its name, and so protected.
// Names are relative, a directory's ends in '/'; a name holding a newline is left out
// too. granpipe's scripts add what they write into a finished run (report.html, pooled
// tables: scripts/run_manifest.py). Throws InputError.
void write_run_manifest(const std::filesystem::path& dir, const FileRecord& recorded);

// Removes granpipe's report.html from `dir` (a user's file of that name is left): one drawn
// while the run went (`granpipe report DIR`) shows the results so far, and stayed in the
// finished run, listed as its own, after a run with --no-report. Call when the run is
// complete, before its manifest is written; the final report is drawn after it.
void remove_report_of_results_so_far(const std::filesystem::path& dir);

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
