// The output directory and its safety: what --out and --overwrite refuse, a failed run
// recorded in run.log and the marker, and a replacing run that fails leaving the earlier
// run whole. Runs use the real lattice and h5md plugins plus small failing ones.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"
#include "test_files.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// A simulation that fails on its first step.
class DivergingSource : public Source {
 public:
  explicit DivergingSource(const PluginContext&) {}
  FrameContent content() const override { return {}; }
  bool next(Frame&) override { throw std::runtime_error("the simulation diverged"); }
};

// An analyzer that finds its second frame unacceptable.
class PickyAnalyzer : public Analyzer {
 public:
  explicit PickyAnalyzer(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override {
    if (++frames_ == 2) throw InputError("frame 1: expected nothing like it");
  }
  void finish(Results&) override {}

 private:
  int frames_ = 0;
};

// Where ScribblingAnalyzer writes a user's notes while a run goes on, and their names.
fs::path scribble_into;
std::vector<std::string> scribbled{"notes.txt"};
std::string scribbled_text = "mine";

// A user writing notes into a folder while a run goes on.
class ScribblingAnalyzer : public Analyzer {
 public:
  explicit ScribblingAnalyzer(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override {
    for (const std::string& name : scribbled) {
      fs::create_directories((scribble_into / name).parent_path());
      std::ofstream(scribble_into / name) << scribbled_text;
    }
  }
  void finish(Results&) override {}
};

// A user removing the earlier run's folder while the run that replaces it goes on.
class RemovingAnalyzer : public Analyzer {
 public:
  explicit RemovingAnalyzer(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override { fs::remove_all(scribble_into); }
  void finish(Results&) override {}
};

// Where SwappingAnalyzer moves the earlier run while a replacing run goes on.
fs::path archive;

// A user who moves the earlier run's folder away while the run that replaces it goes on,
// leaving a symbolic link to it in its place.
class SwappingAnalyzer : public Analyzer {
 public:
  explicit SwappingAnalyzer(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override {
    if (fs::is_symlink(scribble_into)) return;
    fs::rename(scribble_into, archive);
    fs::create_directory_symlink(archive, scribble_into);
  }
  void finish(Results&) override {}
};

// An analyzer that draws each frame into a file of its own, named as plugins name theirs.
class DrawingAnalyzer : public Analyzer {
 public:
  explicit DrawingAnalyzer(const PluginContext& ctx) : files_(ctx.output_files()) {}
  void consume(const Frame& frame, FrameCache&) override {
    std::ofstream(files_.path("_" + std::to_string(frame.step) + ".svg")) << "<svg/>";
  }
  void finish(Results&) override {}

 private:
  OutputFiles files_;
};

Registry registry() {
  Registry r;
  load_plugins(r, plugin_search_path());
  r.add_source<DivergingSource>("diverging", "fails at once", Schema{});
  r.add_analyzer<PickyAnalyzer>("picky", "fails on frame 1", Schema{});
  r.add_analyzer<ScribblingAnalyzer>("scribbling", "writes a note", Schema{});
  r.add_analyzer<DrawingAnalyzer>("drawing", "draws each frame", Schema{});
  r.add_analyzer<RemovingAnalyzer>("removing", "removes the earlier run", Schema{});
  r.add_analyzer<SwappingAnalyzer>("swapping", "links the earlier run from elsewhere", Schema{});
  return r;
}

const char* kLattice = R"({"seed": 1, "source": {"plugin": "lattice",
  "params": {"lattice": "sc", "cells": [2, 2, 2], "jitter": 0.01, "frames": 3}}})";
const char* kDiverging = R"({"source": {"plugin": "diverging"}})";
const char* kPicky = R"({"source": {"plugin": "lattice",
  "params": {"lattice": "sc", "cells": [2, 2, 2], "jitter": 0.01, "frames": 3}},
  "analyzers": [{"plugin": "picky"}]})";
const char* kScribbling = R"({"source": {"plugin": "lattice",
  "params": {"lattice": "sc", "cells": [2, 2, 2], "frames": 2}},
  "analyzers": [{"plugin": "scribbling"}]})";

fs::path fresh_dir(const std::string& name) { return test::fresh_path("outdir", name); }

using test::read_file;

std::string last_line(const fs::path& file) {
  std::string text = read_file(file);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text.substr(text.rfind('\n') + 1);
}

// Every file below `dir` with its content.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = read_file(e.path());
  return files;
}

// Runs `pipeline` into `out`; the InputError's message, or "" when it ran.
std::string run(const std::string& pipeline, const fs::path& out, bool overwrite = false) {
  const Registry r = registry();
  Log log;
  log.set_quiet(true);
  RunOptions o;
  o.progress = false;
  o.out = out;
  o.overwrite = overwrite;
  try {
    Pipeline::parse(pipeline, "p.json", {}, r).run(o, log);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The one directory beside `out` that a run of granpipe built, or nothing.
fs::path only_sibling(const fs::path& out) {
  fs::path found;
  for (const auto& e : fs::directory_iterator(out.parent_path())) {
    if (e.path().filename().string().rfind(out.filename().string() + ".granpipe-", 0) != 0)
      continue;
    EXPECT_EQ(found, fs::path()) << "two directories beside " << out;
    found = e.path();
  }
  return found;
}

// A run's folder as the run leaves it when killed at the start: its marker, pipeline.json
// and run.log, no manifest.
void leave_as_killed(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name != ".granpipe-run" && name != "pipeline.json" && name != "run.log")
      fs::remove(e.path());
  }
}

// --overwrite of the run in `out` refused for what it holds besides, the folder left as it was.
void expect_overwrite_refused_for(const fs::path& out, const std::string& foreign) {
  const auto before = snapshot(out);
  EXPECT_EQ(
      run(kLattice, out, true),
      out.string() +
          ": --overwrite removes only what granpipe wrote, and this run's folder also holds " +
          foreign + "; move them out or remove the folder yourself; nothing was changed");
  EXPECT_EQ(snapshot(out), before);
}

bool marked(const fs::path& dir, const std::string& status) {
  return read_file(dir / ".granpipe-run").find("\"status\":\"" + status + "\"") !=
         std::string::npos;
}

}  // namespace

TEST(FailedRun, AnErrorFromNextIsInRunLogAndMarksTheDirectoryFailed) {
  const fs::path out = fresh_dir("diverging");
  EXPECT_THROW(run(kDiverging, out), std::runtime_error);
  EXPECT_EQ(last_line(out / "run.log"), "failed: the simulation diverged");
  EXPECT_TRUE(marked(out, "failed"));
  EXPECT_EQ(run(kLattice, out),
            out.string() +
                ": expected a new or empty output directory, got one holding a "
                "failed run (its run.log says why); pass --overwrite to replace it, or choose "
                "another --out");
  EXPECT_EQ(run(kLattice, out, true), "");
  EXPECT_TRUE(marked(out, "complete"));
  fs::remove_all(out);
}

TEST(FailedRun, AnErrorFromConsumeIsInRunLogAndLeavesNoResults) {
  const fs::path out = fresh_dir("picky");
  const std::string error = run(kPicky, out);
  EXPECT_EQ(error, "p.json: analyzers[0]: frame 1: expected nothing like it");
  EXPECT_EQ(last_line(out / "run.log"), "failed: " + error);
  EXPECT_TRUE(marked(out, "failed"));
  EXPECT_FALSE(fs::exists(out / "results.h5"));
  EXPECT_FALSE(fs::exists(out / "frames.h5"));
  fs::remove_all(out);
}

TEST(ReplacingRun, AFailureLeavesTheEarlierRunWholeAndItsOwnFilesBeside) {
  const fs::path out = fresh_dir("replace_fails");
  ASSERT_EQ(run(kLattice, out), "");
  const auto before = snapshot(out);
  EXPECT_THROW(run(kDiverging, out, true), std::runtime_error);
  EXPECT_EQ(snapshot(out), before);
  const fs::path beside = only_sibling(out);
  EXPECT_TRUE(marked(beside, "failed"));
  EXPECT_EQ(last_line(beside / "run.log"), "the earlier run in " + out.string() + " is untouched");
  fs::remove_all(beside);
  EXPECT_EQ(run(kPicky, out, true), "p.json: analyzers[0]: frame 1: expected nothing like it");
  EXPECT_EQ(snapshot(out), before);
  EXPECT_TRUE(marked(only_sibling(out), "failed"));
  fs::remove_all(only_sibling(out));
  fs::remove_all(out);
}

TEST(ReplacingRun, SuccessSwapsTheNewRunInAndRemovesTheEarlierOne) {
  const fs::path out = fresh_dir("replace_works");
  ASSERT_EQ(run(kLattice, out), "");
  const std::string earlier = read_file(out / ".granpipe-run");
  ASSERT_EQ(run(std::string(kLattice).replace(std::string(kLattice).find("\"seed\": 1"), 9,
                                              "\"seed\": 2"),
                out, true),
            "");
  EXPECT_NE(read_file(out / ".granpipe-run"), earlier);
  EXPECT_NE(read_file(out / "pipeline.json").find("\"seed\": 2"), std::string::npos);
  EXPECT_TRUE(marked(out, "complete"));
  EXPECT_EQ(only_sibling(out), fs::path());
  fs::remove_all(out);
}

TEST(OutputDirectory, OverwriteRefusesADirectoryWithoutTheMarker) {
  const fs::path out = fresh_dir("users");
  fs::create_directories(out);
  std::ofstream(out / "pipeline.json") << "{}";
  EXPECT_EQ(
      run(kLattice, out, true),
      out.string() +
          ": --overwrite replaces only directories granpipe made (they hold a .granpipe-run "
          "file), got one without (if an older granpipe, which wrote no marker, made it: remove "
          "it yourself); nothing was changed");
  EXPECT_EQ(read_file(out / "pipeline.json"), "{}");
  fs::remove_all(out);
}

TEST(OutputDirectory, RefusesAFileASymlinkAndWhatHoldsTheWorkingDirectory) {
  const fs::path dir = fresh_dir("kinds");
  fs::create_directories(dir / "real");
  std::ofstream(dir / "file") << "mine";
  fs::create_directory_symlink(dir / "real", dir / "link");
  EXPECT_EQ(run(kLattice, dir / "file"),
            (dir / "file").string() + ": expected a directory, got a regular file");
  const std::string symlink = (dir / "link").string() +
                              ": expected a directory, got a symlink (to " +
                              (dir / "real").string() + "); give the directory itself as --out";
  EXPECT_EQ(run(kLattice, dir / "link"), symlink);
  EXPECT_EQ(run(kLattice, (dir / "link").string() + "/", true), symlink);
  const fs::path cwd = fs::current_path();
  fs::current_path(dir / "real");
  EXPECT_EQ(run(kLattice, ".", true), ".: expected a directory of the run's own, got " +
                                          fs::canonical(dir / "real").string() +
                                          ", which is the working directory; choose another --out");
  EXPECT_EQ(run(kLattice, "..", true),
            "..: expected a directory of the run's own, got " + fs::canonical(dir).string() +
                ", which holds the working directory; choose another --out");
  fs::current_path(cwd);
  EXPECT_TRUE(fs::is_empty(dir / "real"));
  EXPECT_EQ(read_file(dir / "file"), "mine");
  fs::remove_all(dir);
}

// out/x/. --overwrite ran to the end, then could not swap out/x for itself and left the
// new run hidden inside the old one; out/missing/../x made out/missing and blamed another
// run. Both refused before anything is made; a leading .. is the working directory's.
TEST(OutputDirectory, RefusesDotsAfterANamedFolder) {
  const fs::path dir = fresh_dir("dots");
  EXPECT_EQ(run(kLattice, dir / "run"), "");
  const auto why = [](const std::string& part, const std::string& after) {
    return ": expected an output directory without . or .. after its first named folder, got \"" +
           part + "\" after \"" + after +
           "\"; write the folder it means (a run into out/x/. would be swapped into itself, and "
           "out/missing/.. made missing/)";
  };
  EXPECT_EQ(run(kLattice, dir / "run" / ".", true), (dir / "run" / ".").string() + why(".", "run"));
  EXPECT_EQ(run(kLattice, dir / "missing" / ".." / "run", true),
            (dir / "missing" / ".." / "run").string() + why("..", "missing"));
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_TRUE(marked(dir / "run", "complete"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
  const fs::path cwd = fs::current_path();
  fs::create_directories(dir / "work");
  fs::current_path(dir / "work");
  EXPECT_EQ(run(kLattice, "../second"), "");
  fs::current_path(cwd);
  EXPECT_TRUE(marked(dir / "second", "complete"));
  fs::remove_all(dir);
}

TEST(OutputDirectory, RefusesToReplaceADirectoryHoldingAnInputFile) {
  const fs::path out = fresh_dir("input_inside");
  ASSERT_EQ(
      run(R"({"source": {"plugin": "lattice", "params": {"lattice": "sc", "cells": [2, 2, 2]}}})",
          out),
      "");
  const std::string frames = (out / "frames.h5").string();
  const std::string reprocess =
      R"({"source": {"plugin": "h5md", "params": {"file": ")" + frames + R"("}}})";
  const auto before = snapshot(out);
  EXPECT_EQ(run(reprocess, out, true),
            "p.json: source.params.file: expected a file outside the output directory " +
                out.string() + ", got \"" + frames +
                "\" inside it; granpipe never writes where it reads (choose another --out)");
  EXPECT_EQ(snapshot(out), before);
  fs::remove_all(out);
}

// The folder of an earlier run with a user's note and a folder of the user's plots in it.
fs::path run_with_users_files(const std::string& name) {
  const fs::path out = fresh_dir(name);
  EXPECT_EQ(run(kLattice, out), "");
  std::ofstream(out / "notes.txt") << "mine";
  fs::create_directories(out / "plots");
  std::ofstream(out / "plots" / "a.svg") << "mine";
  return out;
}

TEST(OutputDirectory, OverwriteRefusesARunFolderHoldingWhatTheRunDidNotWrite) {
  const fs::path out = run_with_users_files("users_notes");
  const auto before = snapshot(out);
  EXPECT_EQ(run(kLattice, out, true),
            out.string() +
                ": --overwrite removes only what granpipe wrote, and this run's folder also holds "
                "notes.txt, plots/; move them out or remove the folder yourself; nothing was "
                "changed");
  EXPECT_EQ(snapshot(out), before);
  fs::remove(out / "notes.txt");
  fs::remove_all(out / "plots");
  EXPECT_EQ(run(kLattice, out, true), "");
  fs::remove_all(out);
}

TEST(OutputDirectory, AManifestListsWhatTheRunWroteAndNothingElse) {
  const fs::path out = fresh_dir("manifest");
  ASSERT_EQ(run(kLattice, out), "");
  std::istringstream listed(read_file(out / ".granpipe-manifest"));
  std::string line;
  std::getline(listed, line);
  EXPECT_EQ(line, "# granpipe run manifest: what the run wrote here");
  std::set<std::string> names;
  while (std::getline(listed, line)) names.insert(line);
  std::set<std::string> present;
  for (const auto& e : fs::directory_iterator(out)) present.insert(e.path().filename().string());
  EXPECT_EQ(names, present);
  EXPECT_TRUE(names.count("frames.h5") && names.count("results.h5") && names.count("run.log"));
  fs::remove_all(out);
}

TEST(OutputDirectory, AFailedRunListsWhatItWroteSoOverwriteReplacesIt) {
  const fs::path out = fresh_dir("failed_manifest");
  EXPECT_THROW(run(kDiverging, out), std::runtime_error);
  EXPECT_NE(read_file(out / ".granpipe-manifest").find("\nrun.log\n"), std::string::npos);
  std::ofstream(out / "notes.txt") << "mine";
  EXPECT_NE(run(kLattice, out, true).find("also holds notes.txt;"), std::string::npos);
  fs::remove(out / "notes.txt");
  EXPECT_EQ(run(kLattice, out, true), "");
  fs::remove_all(out);
}

// A run killed outright wrote no manifest: only the files every run writes before its
// end may go.
TEST(OutputDirectory, AKilledRunWithoutManifestLosesOnlyWhatEveryRunWritesFirst) {
  const fs::path out = fresh_dir("killed");
  ASSERT_EQ(run(kLattice, out), "");
  fs::remove(out / ".granpipe-manifest");
  const std::string refusal = run(kLattice, out, true);
  EXPECT_NE(refusal.find("also holds "), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("results.h5"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find(" (its run left no list of what it wrote: it was killed, or an older "
                         "granpipe made it); "),
            std::string::npos)
      << refusal;
  EXPECT_EQ(refusal.find("pipeline.json"), std::string::npos) << refusal;
  EXPECT_EQ(refusal.find("run.log"), std::string::npos) << refusal;
  leave_as_killed(out);
  std::ofstream(out / "frames.partial.h5") << "\x89HDF\r\n\x1a\n frames so far";
  std::ofstream(out / "report.html") << "<p>my own report</p>";
  EXPECT_NE(run(kLattice, out, true).find("also holds report.html (its run left no list"),
            std::string::npos);
  std::ofstream(out / "report.html") << "<meta name=generator content=\"granpipe report\">";
  EXPECT_EQ(run(kLattice, out, true), "");
  fs::remove_all(out);
}

// Named like them is not enough: a user's notes saved as run.log in a folder point_007 of
// their own (or a pipeline.json, a frames.partial.h5) in a killed run's folder went with
// --overwrite.
TEST(OutputDirectory, AKilledRunsFilesAreKnownByWhatTheyHoldNotByTheirNames) {
  const fs::path out = fresh_dir("killed_named");
  ASSERT_EQ(run(kLattice, out), "");
  leave_as_killed(out);
  fs::create_directory(out / "point_007");
  for (const char* name : {"run.log", "pipeline.json", "frames.partial.h5"}) {
    std::ofstream(out / "point_007" / name) << "my notes";
    const std::string refusal = run(kLattice, out, true);
    EXPECT_NE(refusal.find(std::string("also holds point_007/") + name + " (its run left no list"),
              std::string::npos)
        << refusal;
    fs::remove(out / "point_007" / name);
  }
  std::ofstream(out / "point_007" / "pipeline.json") << "{}";
  EXPECT_NE(run(kLattice, out, true).find("also holds point_007/pipeline.json"), std::string::npos);
  fs::remove(out / "point_007" / "pipeline.json");
  // A FIFO of that name was read, and --overwrite hung on it.
  ASSERT_EQ(::mkfifo((out / "point_007" / "run.log").c_str(), 0600), 0);
  EXPECT_NE(run(kLattice, out, true).find("also holds point_007/run.log"), std::string::npos);
  fs::remove(out / "point_007" / "run.log");
  EXPECT_EQ(run(kLattice, out, true), "");  // the run's own, and an empty point folder
  fs::remove_all(out);
}

TEST(OutputDirectory, OverwriteNeverFollowsASymlinkInTheEarlierRun) {
  const fs::path out = fresh_dir("inner_link");
  const fs::path elsewhere = fresh_dir("inner_link_target");
  fs::create_directories(elsewhere);
  std::ofstream(elsewhere / "results.h5") << "mine";
  ASSERT_EQ(run(kLattice, out), "");
  fs::create_directory_symlink(elsewhere, out / "point_000");
  EXPECT_NE(run(kLattice, out, true).find("also holds point_000;"), std::string::npos);
  EXPECT_EQ(read_file(elsewhere / "results.h5"), "mine");
  fs::remove(out / "point_000");
  fs::remove_all(out);
  fs::remove_all(elsewhere);
}

// The manifest listed every entry of the folder when the run ended, so a note a user wrote
// into a fresh run's folder while it went on counted as the run's, and a later --overwrite
// removed it without a word; then every file named like a stage's (scribbling_notes.txt,
// source.todo) still was. Only what the run recorded as it wrote it is listed.
TEST(OutputDirectory, WhatAUserAddsToAFreshRunsFolderIsNotTheRuns) {
  const fs::path out = fresh_dir("scribbled_fresh");
  scribble_into = out;
  scribbled = {"notes.txt", "scribbling_notes.txt", "source.todo"};
  ASSERT_EQ(run(kScribbling, out), "");
  scribbled = {"notes.txt"};
  for (const char* note : {"notes.txt", "scribbling_notes.txt", "source.todo"})
    EXPECT_EQ(read_file(out / ".granpipe-manifest").find(note), std::string::npos) << note;
  const auto before = snapshot(out);
  EXPECT_EQ(run(kLattice, out, true),
            out.string() +
                ": --overwrite removes only what granpipe wrote, and this run's folder also holds "
                "notes.txt, scribbling_notes.txt, source.todo; move them out or remove the folder "
                "yourself; nothing was changed");
  EXPECT_EQ(snapshot(out), before);
  fs::remove_all(out);
}

// `granpipe report DIR` while a run goes draws the results so far; after a run with
// --no-report that page stayed, listed as the run's. A user's report.html is theirs.
TEST(OutputDirectory, AReportOfTheResultsSoFarIsGoneWhenTheRunIsComplete) {
  const fs::path out = fresh_dir("report_so_far");
  scribble_into = out;
  scribbled = {"report.html"};
  scribbled_text = "<html><meta name=generator content=\"granpipe report\"> so far";
  ASSERT_EQ(run(kScribbling, out), "");
  EXPECT_FALSE(fs::exists(out / "report.html"));
  EXPECT_EQ(read_file(out / ".granpipe-manifest").find("report.html"), std::string::npos);
  fs::remove_all(out);
  scribbled_text = "mine";  // a user's page of that name
  ASSERT_EQ(run(kScribbling, out), "");
  EXPECT_EQ(read_file(out / "report.html"), "mine");
  EXPECT_EQ(read_file(out / ".granpipe-manifest").find("report.html"), std::string::npos);
  scribbled = {"notes.txt"};
  fs::remove_all(out);
}

// A plugin's own files, named with ctx.output_files(), are the run's: listed, and replaced.
TEST(OutputDirectory, APluginsOwnFilesAreListedAndReplaced) {
  const fs::path out = fresh_dir("drawn");
  const std::string drawing = R"({"source": {"plugin": "lattice",
    "params": {"lattice": "sc", "cells": [2, 2, 2], "frames": 2}},
    "analyzers": [{"plugin": "drawing"}]})";
  ASSERT_EQ(run(drawing, out), "");
  const std::string manifest = read_file(out / ".granpipe-manifest");
  EXPECT_NE(manifest.find("\ndrawing_0.svg\n"), std::string::npos) << manifest;
  EXPECT_NE(manifest.find("\ndrawing_1.svg\n"), std::string::npos) << manifest;
  EXPECT_EQ(run(kLattice, out, true), "");
  EXPECT_FALSE(fs::exists(out / "drawing_0.svg"));
  fs::remove_all(out);
}

// A user who writes into the earlier run's folder while the new run goes on keeps the
// note: the new run removes the earlier one's files and leaves the folder with the note.
TEST(ReplacingRun, WhatAUserAddsDuringTheRunIsLeftInTheEarlierFolder) {
  const fs::path out = fresh_dir("scribbled");
  ASSERT_EQ(run(kLattice, out), "");
  scribble_into = out;
  ASSERT_EQ(run(kScribbling, out, true), "");
  EXPECT_TRUE(marked(out, "complete"));
  EXPECT_FALSE(fs::exists(out / "notes.txt"));
  const fs::path earlier = only_sibling(out);
  ASSERT_NE(earlier, fs::path());
  // Not the new run's temporary name, which the docs say may be deleted.
  EXPECT_EQ(earlier.filename().string().rfind(out.filename().string() + ".granpipe-old-", 0), 0u)
      << earlier;
  EXPECT_EQ(snapshot(earlier), (std::map<std::string, std::string>{{"notes.txt", "mine"}}));
  fs::remove_all(earlier);
  fs::remove_all(out);
}

// The earlier run removed while the new one went: the swap failed with "No such file or
// directory; the earlier run is untouched", and the complete new run was marked failed.
TEST(ReplacingRun, AnEarlierRunRemovedMeanwhileLeavesTheNewOneInItsPlace) {
  const fs::path out = fresh_dir("removed");
  ASSERT_EQ(run(kLattice, out), "");
  scribble_into = out;
  const std::string removing = R"({"source": {"plugin": "lattice",
    "params": {"lattice": "sc", "cells": [2, 2, 2], "frames": 2}},
    "analyzers": [{"plugin": "removing"}]})";
  ASSERT_EQ(run(removing, out, true), "");
  EXPECT_TRUE(marked(out, "complete"));
  EXPECT_TRUE(fs::exists(out / "results.h5"));
  EXPECT_EQ(only_sibling(out), fs::path());
  fs::remove_all(out);
}

// A manifest edited by hand (with a forged marker) listing a folder of the user's and its
// file: --overwrite removed both, exit 0. A run lists no folder but point_NNN.
TEST(OutputDirectory, AManifestIsNotBelievedBeyondWhereARunWrites) {
  const fs::path out = fresh_dir("forged");
  ASSERT_EQ(run(kLattice, out), "");
  fs::create_directory(out / "keep");
  std::ofstream(out / "keep" / "k.txt") << "mine";
  std::ofstream(out / ".granpipe-manifest", std::ios::app) << "keep/\nkeep/k.txt\n";
  EXPECT_EQ(run(kLattice, out, true),
            out.string() +
                ": --overwrite removes only what granpipe wrote, and this run's folder also holds "
                "keep/; move them out or remove the folder yourself; nothing was changed");
  EXPECT_EQ(read_file(out / "keep" / "k.txt"), "mine");
  fs::remove_all(out);
}

// A report.html of the user's put where the run's had been was removed by --overwrite: the
// manifest listed the name, and the file was not looked at.
TEST(OutputDirectory, AListedNameIsNotTheRunsWhenItsFileIsAnothers) {
  const fs::path out = fresh_dir("report_replaced");
  ASSERT_EQ(run(kLattice, out), "");
  std::ofstream(out / "report.html") << "my own annotated report";
  std::ofstream(out / ".granpipe-manifest", std::ios::app) << "report.html\n";
  expect_overwrite_refused_for(out, "report.html");
  fs::remove_all(out);
}

// A point_007 folder put into the folder of a run without a sweep while it went was listed
// as the run's, and --overwrite removed it with what it held.
TEST(OutputDirectory, APointFolderTheRunDidNotMakeIsNotTheRuns) {
  const fs::path out = fresh_dir("point_added");
  scribble_into = out;
  scribbled = {"point_007/frames.h5", "point_007/results.h5"};
  ASSERT_EQ(run(kScribbling, out), "");
  scribbled = {"notes.txt"};
  EXPECT_EQ(read_file(out / ".granpipe-manifest").find("point_007"), std::string::npos);
  expect_overwrite_refused_for(out, "point_007/");
  fs::remove_all(out);
}

// The earlier run moved away and linked back into its place while the new run went: the
// swap followed the link and removed the earlier run's files where they now were (exit 0).
TEST(ReplacingRun, AnEarlierRunLinkedFromElsewhereIsLeftWhereItIs) {
  const fs::path out = fresh_dir("linked");
  archive = fresh_dir("linked_archive");
  ASSERT_EQ(run(kLattice, out), "");
  const auto before = snapshot(out);
  scribble_into = out;
  const std::string swapping = R"({"source": {"plugin": "lattice",
    "params": {"lattice": "sc", "cells": [2, 2, 2], "frames": 2}},
    "analyzers": [{"plugin": "swapping"}]})";
  const std::string message = run(swapping, out, true);
  EXPECT_EQ(message.rfind(out.string() + ": expected the earlier run's folder, got something "
                                         "else put there while this run went (a symbolic "
                                         "link?); it is left as it is and this run is in ",
                          0),
            0u)
      << message;
  EXPECT_TRUE(fs::is_symlink(out));
  EXPECT_EQ(snapshot(archive), before);
  const fs::path built = only_sibling(out);
  EXPECT_TRUE(fs::exists(built / "results.h5"));
  fs::remove_all(built);
  fs::remove(out);
  fs::remove_all(archive);
}

// --overwrite of a run made in a folder of the user's, private (0700): the new folder came
// back world-readable.
TEST(ReplacingRun, TheNewFolderKeepsTheEarlierOnesPermissions) {
  const fs::path out = fresh_dir("private");
  ASSERT_EQ(mkdir(out.c_str(), 0700), 0);
  ASSERT_EQ(run(kLattice, out), "");
  ASSERT_EQ(run(kLattice, out, true), "");
  struct stat s;
  ASSERT_EQ(stat(out.c_str(), &s), 0);
  EXPECT_EQ(s.st_mode & 0777, 0700u);
  fs::remove_all(out);
}

// A file the run writes at its end, put in the run's folder by the user while it went (their
// own results.h5, frames.h5, a CSV of the run's name): renamed over, exit 0. Refused, left.
TEST(OutputDirectory, AFileTheRunWritesAtItsEndIsNotRenamedOverAUsers) {
  for (const char* name : {"results.h5", "frames.h5"}) {
    const fs::path out = fresh_dir(std::string("end_") + name);
    scribble_into = out;
    scribbled = {name};
    const std::string message = run(kScribbling, out);
    scribbled = {"notes.txt"};
    EXPECT_EQ(message.rfind((out / name).string() +
                                ": expected no file of this name (the run writes it at its end), "
                                "got one put there while the run went (not granpipe's: left as it "
                                "is); the run's is ",
                            0),
              0u)
        << message;
    EXPECT_EQ(read_file(out / name), "mine") << name;
    EXPECT_NE(run(kLattice, out, true).find(std::string("also holds ") + name), std::string::npos);
    EXPECT_EQ(read_file(out / name), "mine") << name;
    fs::remove_all(out);
  }
}

// A file of the user's at a temporary name the run writes its results under: the run stops
// leaving it, and it was still listed as the run's, so --overwrite removed it (exit 0).
TEST(OutputDirectory, AFileTheRunRefusedToWriteThroughIsNotListedAsTheRuns) {
  const fs::path out = fresh_dir("planted_tmp");
  scribble_into = out;
  scribbled = {"results.h5.tmp"};
  const std::string message = run(kScribbling, out);
  scribbled = {"notes.txt"};
  EXPECT_NE(message.find("results.h5.tmp: expected no file at this temporary name"),
            std::string::npos)
      << message;
  EXPECT_EQ(read_file(out / "results.h5.tmp"), "mine");
  EXPECT_NE(run(kLattice, out, true).find("also holds results.h5.tmp"), std::string::npos);
  EXPECT_EQ(read_file(out / "results.h5.tmp"), "mine");
  fs::remove_all(out);
}
