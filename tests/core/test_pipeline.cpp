// Pipeline reading and running with small in-test plugins: every class of bad input
// gives one line naming file, JSON path, expected and found; sweeps expand; runs are
// reproducible; output directories are never overwritten silently.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "granpipe/frame_store.hpp"
#include "granpipe/pipeline.hpp"
#include "test_files.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

// Emits `frames` frames of `n` random points in a unit periodic box.
class RandomSource : public Source {
 public:
  explicit RandomSource(const PluginContext& c)
      : frames_(c.params.integer("frames")),
        n_(c.params.integer("n")),
        rng_(c.seeds.stream("points")) {}
  FrameContent content() const override { return {.dim = 2}; }
  bool next(Frame& f) override {
    if (emitted_ == frames_) return false;
    f.resize(n_, 2);
    f.container = Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
    for (Eigen::Index i = 0; i < n_; ++i) {
      f.position()(i, 0) = rng_.uniform();
      f.position()(i, 1) = rng_.uniform();
    }
    f.radius().setConstant(0.01);
    f.step = emitted_++;
    return true;
  }

 private:
  std::int64_t frames_, n_, emitted_ = 0;
  RandomStream rng_;
};

// Emits `frames` frames of one point, each into a frame it finds empty: the runner frees a
// frame before the source makes the next (a DEM run then holds one frame beside its engine,
// not two).
class WantsAnEmptyFrame : public Source {
 public:
  explicit WantsAnEmptyFrame(const PluginContext& c) : frames_(c.params.integer("frames")) {}
  FrameContent content() const override { return {.dim = 2}; }
  bool next(Frame& f) override {
    if (f.size() != 0 || f.contacts) throw InputError("was handed a frame that is not empty");
    if (emitted_ == frames_) return false;
    f.resize(1, 2);
    f.container = Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones());
    f.radius().setConstant(0.01);
    f.add_contacts(0);
    f.step = emitted_++;
    return true;
  }

 private:
  std::int64_t frames_, emitted_ = 0;
};

class MeanXAnalyzer : public Analyzer {
 public:
  explicit MeanXAnalyzer(const PluginContext& c) : scale_(c.params.real("scale")) {}
  void consume(const Frame& f, FrameCache&) override {
    mean_.add(f.position().col(0).mean() * scale_);
  }
  void finish(Results& r) override { r.add_scalar("mean_x", mean_.mean(), mean_.standard_error()); }

 private:
  double scale_;
  RunningMean mean_;
};

class NeedsSupports : public Analyzer {
 public:
  explicit NeedsSupports(const PluginContext&) {}
  FrameContent needs() const override {
    return {.dim = 2, .columns = {{"supports", Scope::Particle, ValueType::Integer, 2, "", ""}}};
  }
  void consume(const Frame&, FrameCache&) override {}
  void finish(Results&) override {}
};

// Refuses in finish() what it saw (an analyzer that needs a whole run to judge its data).
class RefusesAtTheEnd : public Analyzer {
 public:
  explicit RefusesAtTheEnd(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override {}
  void finish(Results&) override { throw InputError("expected at least 5 frames, got 4"); }
};

// Gives "extra" only when its flag is on: a result some sweep points have and others not.
class ExtraWhenFlagged : public Analyzer {
 public:
  explicit ExtraWhenFlagged(const PluginContext& c) : flag_(c.params.boolean("flag")) {}
  void consume(const Frame&, FrameCache&) override {}
  void finish(Results& r) override {
    if (flag_) r.add_scalar("extra", 7.0);
  }

 private:
  bool flag_;
};

// Warns of the points of each frame it sees, as analyzers warn of undefined results.
class SaysItsPoints : public Analyzer {
 public:
  explicit SaysItsPoints(const PluginContext& c) : log_(c.log) {}
  void consume(const Frame& f, FrameCache&) override {
    log_.warn("says: " + std::to_string(f.size()) + " points");
  }
  void finish(Results&) override {}

 private:
  Log& log_;
};

Registry test_registry() {
  Registry r;
  Schema s;
  s.integer("frames", 3, "frames to emit").min(1);
  s.integer("n", 10, "points per frame").range(1, 1000);
  r.add_source<RandomSource>("random", "random points", s);
  Schema a;
  a.real("scale", 1.0, "factor").min(0, true);
  r.add_analyzer<MeanXAnalyzer>("meanx", "mean x", a);
  r.add_analyzer<NeedsSupports>("needs_supports", "needs support labels", Schema{});
  r.add_analyzer<RefusesAtTheEnd>("refuses_at_the_end", "refuses its data in finish()", Schema{});
  Schema f;
  f.boolean("flag", false, "give the extra result");
  r.add_analyzer<ExtraWhenFlagged>("extra_when_flagged", "a result only when flagged", f);
  r.add_analyzer<SaysItsPoints>("says", "warns of each frame's points", Schema{});
  return r;
}

std::string error_of(const std::string& text, const std::vector<std::string>& sets = {}) {
  const Registry r = test_registry();
  try {
    Pipeline::parse(text, "p.json", sets, r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kGood = R"({
  "name": "t", "seed": 5,
  "source": {"plugin": "random", "params": {"frames": 4}},
  "analyzers": [{"plugin": "meanx", "params": {"scale": 2.0}}]
})";

fs::path fresh_dir(const std::string& name) { return test::fresh_path("pipeline", name); }

// Run options without progress output (each test sets its own output directory).
RunOptions quiet_options() {
  RunOptions o;
  o.progress = false;
  return o;
}

// The message of the InputError a quiet run of `p` on one thread throws, in a fresh
// directory of this name (removed after); "no error" when it runs through.
std::string refusal_of_run(const Pipeline& p, const std::string& dir) {
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.out = fresh_dir(dir);
  o.threads = 1;
  std::string message = "no error";
  try {
    p.run(o, log);
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::remove_all(*o.out);
  return message;
}

}  // namespace

TEST(PipelineErrors, MalformedJsonNamesLineAndColumn) {
  const std::string e = error_of("{\n  \"name\": \"x\",\n  \"seed\": ,\n}");
  EXPECT_EQ(e.rfind("p.json:3:11: malformed JSON:", 0), 0u) << e;
}

// The parser took a NUL byte for the end of the file: a pipeline with one after its first
// object ran without what followed (another seed, more analyzers), exit 0.
TEST(PipelineErrors, ANulByteIsRefusedWhereItIs) {
  using namespace std::string_literals;
  EXPECT_EQ(error_of("{\"seed\": 3}\0, \"seed\": 99}"s),
            "p.json:1:12: malformed JSON: expected text, got a NUL byte (is it a binary file?)");
}

// A frame_stride of 2^63 wrapped below 1 and was called no integer; 1e3 was refused, though
// plugins take it as 1000.
TEST(PipelineErrors, FrameStrideIsReadAsPluginsReadIntegers) {
  EXPECT_EQ(error_of(kGood, {"output.frame_stride=9223372036854775808"}),
            "--set output.frame_stride=9223372036854775808: expected an integer >= 1, got "
            "9223372036854775808 (beyond 2^63 - 1, the largest integer)");
  EXPECT_EQ(error_of(kGood, {"output.frame_stride=1e3"}), "no error");
}

// A \u0000 in a string cut a file name short where it was opened (the file before the
// NUL was read, the pipeline recording the whole name) and an output folder's message.
TEST(PipelineErrors, AnEscapedNulInAStringIsRefusedWhereItIs) {
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}, "output": {"dir": "out/a\u0000b"}})"),
            "p.json: output.dir: expected a string without a NUL character, got one holding "
            "\\u0000");
  EXPECT_EQ(error_of(kGood, {R"(name="a\u0000")"}),
            R"(--set name="a\u0000": expected a string without a NUL character, got one holding )"
            R"(\u0000)");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"a\u0000": 1}}})"),
            "p.json: source.params: expected a key without a NUL character, got one holding "
            "\\u0000");
}

// 64 levels are read; the 65th is refused by a parser that never recurses, so that a
// file nested a hundred thousand levels deep cannot overflow the stack.
TEST(PipelineErrors, NestingDeeperThan64LevelsIsRefused) {
  const auto repeat = [](const std::string& s, int n) {
    std::string out;
    for (int k = 0; k < n; ++k) out += s;
    return out;
  };
  const auto nested = [](int levels) {
    return std::string(levels, '[') + std::string(levels, ']');
  };
  EXPECT_EQ(error_of("{\"description\": " + nested(63) + "}"),
            "p.json: description: expected a string, got " + repeat("[", 57) + "...");
  const std::string deepest = "p.json: description" + repeat("[0]", 63) +
                              ": expected JSON nested at most 64 levels deep, got deeper";
  EXPECT_EQ(error_of("{\"description\": " + nested(64) + "}"), deepest);
  EXPECT_EQ(error_of("{\"description\": " + nested(100000) + "}"), deepest);
  // A --set value sits under its path's levels (source, params, n).
  EXPECT_EQ(error_of(kGood, {"source.params.n=" + nested(100000)}),
            "--set source.params.n=" + repeat("[", 61) + "...: " + repeat("[0]", 61) +
                ": expected JSON nested at most 64 levels deep, got deeper");
  EXPECT_EQ(error_of(kGood, {"source.params" + repeat(".a", 100) + "=1"}),
            "--set source.params" + repeat(".a", 32) +
                "...: expected a path of at most 64 parts, got more");
}

TEST(PipelineErrors, DuplicateKeysAreRefusedNotOverwritten) {
  EXPECT_EQ(error_of(R"({"name": "a", "source": {"plugin": "random"}, "name": "b"})"),
            "p.json: name: expected each key once in an object, got \"name\" again");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"},
                        {"plugin": "meanx", "name": "b", "params": {"scale": 1, "scale": 2}}]})"),
            "p.json: analyzers[1].params.scale: expected each key once in an object, got \"scale\" "
            "again");
  EXPECT_EQ(
      error_of(kGood, {R"(source.params={"n": 1, "n": 2})"}),
      R"(--set source.params={"n": 1, "n": 2}: n: expected each key once in an object, got "n" again)");
}

TEST(PipelineErrors, NumbersBeyondDoubleRangeNameTheirPath) {
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"n": 1e400}}})"),
            "p.json: source.params.n: expected a number of magnitude below 1.8e308, got 1e400");
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.n": [1, -2E+999]}}})"),
      "p.json: sweep.parameters.source.params.n[1]: expected a number of magnitude below 1.8e308, "
      "got -2E+999");
  EXPECT_EQ(error_of(kGood, {"source.params.n=1e400"}),
            "--set source.params.n=1e400: expected a number of magnitude below 1.8e308, got 1e400");
}

TEST(PipelineErrors, UnknownTopLevelKeyGetsDidYouMean) {
  const std::string e = error_of(R"({"source": {"plugin": "random"}, "analyzer": []})");
  EXPECT_EQ(
      e,
      "p.json: analyzer: unknown key (did you mean \"analyzers\"?); known: name, description, "
      "seed, source, analyzers, writers, output, sweep, report");
}

TEST(PipelineErrors, UnknownParameterGetsDidYouMean) {
  const std::string e = error_of(R"({"source": {"plugin": "random", "params": {"frams": 2}}})");
  EXPECT_EQ(e,
            "p.json: source.params.frams: unknown parameter (did you mean \"frames\"?); known: "
            "frames, n");
}

TEST(PipelineErrors, WrongType) {
  const std::string e = error_of(
      R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}, {"plugin": "meanx", "name": "b", "params": {"scale": "five"}}]})");
  EXPECT_EQ(e, "p.json: analyzers[1].params.scale: expected a number > 0, got \"five\"");
}

TEST(PipelineErrors, OutOfRangeAndNonInteger) {
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"n": 0}}})"),
            "p.json: source.params.n: expected an integer in [1, 1000], got 0");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"frames": 2.5}}})"),
            "p.json: source.params.frames: expected an integer >= 1, got 2.5");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"n": 2e3}}})"),
            "p.json: source.params.n: expected an integer in [1, 1000], got 2000.0");
  // Whole, but no integer parameter: said why (the bare message left the reader to guess).
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"frames": 1e19}}})"),
            "p.json: source.params.frames: expected an integer >= 1, got 1e+19 (with a point or "
            "an exponent a number is an exact integer only below 9e15; write larger ones in "
            "digits)");
  EXPECT_EQ(
      error_of(R"({"source": {"plugin": "random", "params": {"frames": 10000000000000000000}}})"),
      "p.json: source.params.frames: expected an integer >= 1, got 10000000000000000000 (beyond "
      "2^63 - 1, the largest integer)");
}

TEST(PipelineErrors, UnknownPluginAndWrongKind) {
  EXPECT_EQ(error_of(R"({"source": {"plugin": "randon"}})"),
            "p.json: source.plugin: expected a source plugin, got unknown \"randon\" (did you mean "
            "\"random\"?); known: random");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "meanx"}})"),
            "p.json: source.plugin: expected a source plugin, got \"meanx\", which is an analyzer");
}

TEST(PipelineErrors, DuplicateAnalyzerNames) {
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}, {"plugin": "meanx"}]})"),
      "p.json: analyzers[1].name: expected a name not used by another analyzer or writer, got "
      "\"meanx\" again");
}

TEST(PipelineErrors, AnalyzerNamesArePlainAndFreeOfRunnerGroups) {
  const std::string too_long = "\"" + std::string(101, 'a') + "\"";
  for (const std::string bad : {R"(5)", R"("")", R"("a/b")", R"("..")", R"("a\nb")", R"("a.b")",
                                R"("source")", R"("point_001")", too_long.c_str()}) {
    const std::string text =
        R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx", "name": )" + bad +
        "}]}";
    EXPECT_EQ(error_of(text),
              "p.json: analyzers[0].name: expected a name of at most 100 letters, digits and _, "
              "starting with a letter (not source, sweep or point_*), got " +
                  (bad.size() > 60 ? bad.substr(0, 57) + "...\"" : bad));
  }
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "sweep": {"mode": 3, "parameters": {"source.params.n": [1]}}})"),
      "p.json: sweep.mode: expected one of \"grid\", \"zip\", got 3");
}

// The run's name is the default output directory and goes into every CSV header line.
TEST(PipelineErrors, PipelineNamesCannotLeaveTheOutputFolderOrAddLines) {
  for (const std::string bad : {R"("")", R"("../up")", R"("a/b")", R"("..")", R"(".hidden")",
                                R"("a\nb")", R"("a\u0001b")", R"("a b")", R"(3)"}) {
    EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}, "name": )" + bad + "}"),
              "p.json: name: expected a name of at most 100 letters, digits, _, - and . (not "
              "first), got " +
                  bad);
  }
  EXPECT_EQ(
      error_of(kGood, {R"(name="x\ny")"}),
      R"(--set name="x\ny": expected a name of at most 100 letters, digits, _, - and . (not first), got "x\ny")");
  const Registry r = test_registry();
  EXPECT_EQ(
      Pipeline::parse(R"({"source": {"plugin": "random"}, "name": "run-2.b_3"})", "p.json", {}, r)
          .points(),
      1u);
  try {
    Pipeline::parse(R"({"source": {"plugin": "random"}})", "my pipeline.json", {}, r);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "my pipeline.json: name: expected a name of at most 100 letters, digits, _, - and . "
        "(not first), got none, and the file name \"my pipeline\" is not one");
  }
}

TEST(PipelineErrors, SetOverridesAreValidatedToo) {
  EXPECT_EQ(error_of(kGood, {"source.params.frames=-1"}),
            "--set source.params.frames=-1: expected an integer >= 1, got -1");
  EXPECT_EQ(error_of(kGood, {"source.params.frames"}),
            "--set source.params.frames: expected path=value, got no '='");
  EXPECT_EQ(error_of(kGood, {"seed=-1", "source.params.n=2"}),
            "--set seed=-1: expected an integer >= 0, got -1");
  EXPECT_EQ(
      error_of(kGood, {R"(analyzers[0]={"plugin": "meanx", "params": {"scale": 0}})"}),
      R"(--set analyzers[0]={"plugin": "meanx", "params": {"scale": 0}}: analyzers[0].params.scale: )"
      "expected a number > 0, got 0");
  // What the file says, and what the --set did not touch, is still the file's.
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random", "params": {"n": 0}}})",
                     {"source.params.frames=2"}),
            "p.json: source.params.n: expected an integer in [1, 1000], got 0");
  // A --set of a swept parameter was dropped without a word, the sweep's values run.
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.n": [5000]}}})",
          {"source.params.n=5"}),
      "--set source.params.n=5: expected a value the sweep leaves alone, got source.params.n, "
      "which the sweep sets at every point; give the sweep the values instead: --set "
      "'sweep.parameters.source.params.n=[...]'");
  // Two --set of one value ran with the last, without a word (a script's after a user's).
  EXPECT_EQ(error_of(kGood, {"source.params.n=5", "source.params.n=6"}),
            "--set source.params.n=6: expected a value no other --set gives, got "
            "source.params.n, which --set source.params.n=5 sets too");
  EXPECT_EQ(error_of(kGood, {"source.params.n=5", R"(source.params={"n": 6})"}),
            R"(--set source.params={"n": 6}: expected a value no other --set gives, got )"
            "source.params, which holds source.params.n, which --set source.params.n=5 sets too");
  // A value set inside what a --set before it made is both's.
  EXPECT_EQ(error_of(kGood, {R"(source.params={"n": 6})", "source.params.frames=2"}), "no error");
}

// A --set that put a non-object where a sweep assigns into it was blamed on the sweep
// ("sweep.parameters[...]: expected an object at ..."), though the sweep was the file's.
TEST(PipelineErrors, SetOfParamsThatAreNoObjectIsNamedBeforeTheSweep) {
  const std::string swept =
      R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
          "sweep": {"parameters": {"source.params.n": [5, 6], "analyzers[0].params.scale": [1, 2]}}})";
  EXPECT_EQ(error_of(swept, {"source.params=5"}),
            "--set source.params=5: expected an object of parameters, got 5");
  EXPECT_EQ(error_of(swept, {"analyzers[0].params=[1]"}),
            "--set analyzers[0].params=[1]: expected an object of parameters, got [1]");
}

// One parameter, one spelling: [00] named entry 0 past the check that a --set leaves
// swept values alone, and a sweep of both cells and cells[0] (or of [0] and [00]) set one
// value twice at every point, recording both. A --set of the object holding a swept value
// was replaced there without a word.
TEST(PipelineErrors, ASweptValueIsSetOncePerPoint) {
  const std::string swept =
      R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
          "sweep": {"parameters": {"analyzers[0].params.scale": [1, 2]}}})";
  EXPECT_EQ(error_of(swept, {"analyzers[00].params.scale=3"}),
            "--set analyzers[00].params.scale=3: expected a list index without leading zeros, "
            "got [00] in \"analyzers[00].params.scale\"");
  EXPECT_EQ(error_of(swept, {R"(analyzers[0].params={"scale": 3})"}),
            R"(--set analyzers[0].params={"scale": 3}: expected a value the sweep leaves alone, )"
            "got analyzers[0].params, which holds analyzers[0].params.scale, which the sweep sets "
            "at every point; give the sweep the values instead: --set "
            "'sweep.parameters.analyzers[0].params.scale=[...]'");
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}], "sweep": {"mode": "zip",
              "parameters": {"analyzers[0].params.scale": [1], "analyzers[00].params.scale": [2]}}})"),
      "p.json: sweep.parameters[\"analyzers[00].params.scale\"]: expected a list index without "
      "leading zeros, got [00] in \"analyzers[00].params.scale\"");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}, "sweep": {"parameters": {
                  "source.params.walls": [{"base": 1}], "source.params.walls.base": [2]}}})"),
            "p.json: sweep.parameters[\"source.params.walls.base\"]: expected a parameter no other "
            "swept path holds or is part of, got one overlapping \"source.params.walls\"");
}

// The summary's true was 0 and false 1 (their places in the list), and a result only some
// points gave was left out of it.
TEST(Pipeline, SweepSummaryHoldsBooleansAsOneAndZeroAndEveryPointsResults) {
  const Registry r = test_registry();
  const char* text =
      R"({"seed": 9, "source": {"plugin": "random"}, "analyzers": [{"plugin": "extra_when_flagged"}],
    "output": {"save_frames": false}, "sweep": {"parameters": {"analyzers[0].params.flag": [false, true]}}})";
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.out = fresh_dir("summary");
  const RunSummary run = Pipeline::parse(text, "p.json", {}, r).run(o, log);
  const Table& points = run.results.at("sweep").tables().at("points");
  EXPECT_EQ(points.column("analyzers[0].params.flag"), (std::vector<double>{0.0, 1.0}));
  const std::vector<double>& extra = points.column("extra_when_flagged.extra");
  EXPECT_TRUE(std::isnan(extra[0]));
  EXPECT_EQ(extra[1], 7.0);
  fs::remove_all(*o.out);
}

// A sweep's points warned alike and interleaved: which point spoke? Each line names it; a
// run of one point is no sweep, its lines as they are.
TEST(Pipeline, ASweepPointsWarningsNameThePoint) {
  const Registry r = test_registry();
  const auto warnings_of = [&](const std::string& sweep) {
    const std::string text =
        R"({"source": {"plugin": "random", "params": {"frames": 1}}, "analyzers": [{"plugin": "says"}],
          "output": {"save_frames": false})" +
        sweep + "}";
    Log log;
    log.set_quiet(true);
    RunOptions o = quiet_options();
    o.out = fresh_dir("warnings");
    o.threads = 1;
    Pipeline::parse(text, "p.json", {}, r).run(o, log);
    std::ifstream in(*o.out / "run.log");
    std::vector<std::string> said;
    for (std::string line; std::getline(in, line);)
      if (line.starts_with("warning: ")) said.push_back(line);
    fs::remove_all(*o.out);
    return said;
  };
  EXPECT_EQ(warnings_of(R"(, "sweep": {"parameters": {"source.params.n": [3, 5]}})"),
            (std::vector<std::string>{"warning: point 0: says: 3 points",
                                      "warning: point 1: says: 5 points"}));
  EXPECT_EQ(warnings_of(""), (std::vector<std::string>{"warning: says: 10 points"}));
}

// A --set of one entry of a list was blamed on the file ("p.json: ...: got [1,0]").
TEST(PipelineErrors, SetOfAListEntryIsNamedWhenTheListIsRefused) {
  Registry r = test_registry();
  Schema s;
  s.integers("cells", std::vector<std::int64_t>{3, 3}, "cells").min(1);
  r.add_analyzer<NeedsSupports>("cells", "a list parameter", s);
  try {
    Pipeline::parse(R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "cells",
                        "params": {"cells": [1, 2]}}]})",
                    "p.json", {"analyzers[0].params.cells[1]=0"}, r);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "--set analyzers[0].params.cells[1]=0: analyzers[0].params.cells: expected a "
                 "list of integers >= 1, got [1,0]");
  }
}

TEST(PipelineErrors, SetListIndexBeyond64BitsIsNoEntry) {
  EXPECT_EQ(
      error_of(kGood, {"analyzers[99999999999999999999999].params.scale=1"}),
      "--set analyzers[99999999999999999999999].params.scale=1: expected an existing list entry "
      "analyzers[99999999999999999999999], got a list of 1 entry");
  EXPECT_EQ(error_of(kGood, {"analyzers[1].params.scale=1"}),
            "--set analyzers[1].params.scale=1: expected an existing list entry analyzers[1], got "
            "a list of 1 entry");
}

TEST(PipelineErrors, SetIndexIntoAnObjectSaysItIsAnObject) {
  EXPECT_EQ(error_of(kGood, {"source[0]=1"}),
            "--set source[0]=1: expected a list at \"source\" for [0], got an object");
  EXPECT_EQ(error_of(kGood, {"seed.x=1"}),
            "--set seed.x=1: expected an object at \"seed\" for \"x\", got a number");
}

TEST(PipelineErrors, SweepPathOfAMissingAnalyzerSaysHowManyThereAre) {
  EXPECT_EQ(
      error_of(R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
                         "sweep": {"parameters": {"analyzers[2].params.scale": [1, 2]}}})"),
      "p.json: sweep.parameters[\"analyzers[2].params.scale\"]: expected an existing list entry "
      "analyzers[2], got a list of 1 entry");
  // A --set of the sweep's parameters is named, then the entry (the entry's key was glued
  // to the --set's text).
  EXPECT_EQ(
      error_of(R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}]})",
               {R"(sweep.parameters={"analyzers[2].params.scale": [1, 2]})"}),
      R"(--set sweep.parameters={"analyzers[2].params.scale": [1, 2]}: sweep.parameters["analyzers[2].params.scale"]: )"
      "expected an existing list entry analyzers[2], got a list of 1 entry");
}

// Found by fuzz_pipeline: a bare-word --set value that is not UTF-8 became a JSON string
// that threw when written out (exit 1, "internal error").
TEST(PipelineErrors, SetThatIsNotUtf8IsRefused) {
  EXPECT_EQ(error_of(kGood, {"name=ab\x98\x98n"}),
            "--set name=ab...: expected UTF-8 text, got the byte 0x98 next");
  EXPECT_EQ(error_of(kGood, {"source.params.\xc3=1"}),
            "--set source.params....: expected UTF-8 text, got the byte 0xc3 next");
  // Overlong forms and surrogates are not UTF-8 either; the rest of Unicode is.
  EXPECT_EQ(error_of(kGood, {"name=\xc0\xaf"}),
            "--set name=...: expected UTF-8 text, got the byte 0xc0 next");
  EXPECT_EQ(error_of(kGood, {"name=\xed\xa0\x80"}),
            "--set name=...: expected UTF-8 text, got the byte 0xed next");
  EXPECT_EQ(error_of(kGood, {"description=caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x8e\xb2"}), "no error");
}

TEST(PipelineErrors, SweepValueOutOfRangeNamesThePoint) {
  const std::string e = error_of(
      R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.n": [5, 5000]}}})");
  EXPECT_EQ(e,
            "p.json: source.params.n: expected an integer in [1, 1000], got 5000 (sweep point 1: "
            "source.params.n = 5000)");
  // A sweep written by --set was blamed on the file, which has none.
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}})",
                     {R"(sweep={"parameters": {"source.params.n": [5, 5000]}})"}),
            R"(--set sweep={"parameters": {"source.params.n": [5, 5000]}}: )"
            "expected an integer in [1, 1000], got 5000 (sweep point 1: source.params.n = 5000)");
  EXPECT_EQ(error_of(R"({"source": {"plugin": "random"}, "sweep": {"parameters": {}}})",
                     {R"(sweep.parameters={"source.params.n": [5000]})"}),
            R"(--set sweep.parameters={"source.params.n": [5000]}: )"
            "expected an integer in [1, 1000], got 5000 (sweep point 0: source.params.n = 5000)");
}

// A sweep's size is known from its lists' lengths: too many points are refused before
// any is made (a small file could ask for 10^9).
TEST(PipelineErrors, SweepOfTooManyPointsIsRefusedBeforeExpanding) {
  const auto list = [](int n) {
    std::string s = "[1";
    for (int k = 1; k < n; ++k) s += ", 1";
    return s + "]";
  };
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}], "sweep": {"parameters": {
                        "source.params.n": )" +
          list(1000) + R"(, "source.params.frames": )" + list(1000) +
          R"(, "analyzers[0].params.scale": )" + list(1000) + "}}}"),
      "p.json: sweep.parameters: expected at most 100000 sweep points, got 1e+09 (grid of 1000 x "
      "1000 x 1000 values)");
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "sweep": {"mode": "zip", "parameters": {"source.params.n": )" +
          list(100001) + "}}}"),
      "p.json: sweep.parameters: expected at most 100000 sweep points, got 100001 (zip of 100001 "
      "values)");
  const Registry r = test_registry();
  const std::string at_limit =
      R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.n": )" +
      list(100) + R"(, "source.params.frames": )" + list(1000) + "}}}";
  EXPECT_EQ(Pipeline::parse(at_limit, "p.json", {}, r).points(), 100000u);
}

TEST(PipelineErrors, SweepPathsAreCheckedWithoutRecursion) {
  const std::string name(200000, 'a');
  EXPECT_EQ(
      error_of(R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.)" +
               name + R"(": [1]}}})"),
      "p.json: source.params." + name +
          ": unknown parameter; known: frames, n (sweep point 0: source.params." + name + " = 1)");
  EXPECT_EQ(
      error_of(R"({"source": {"plugin": "random"}, "sweep": {"parameters": {"source.params.n+)" +
               name + R"(": [1]}}})"),
      "p.json: sweep.parameters[\"source.params.n+aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...\"]: "
      "expected a plugin "
      "parameter path like source.params.name or analyzers[0].params.name, got "
      "\"source.params.n+aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa...\"");
}

TEST(PipelineErrors, AnalyzerNeedsWhatTheSourceLacks) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(
      R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "needs_supports"}]})", "p.json",
      {}, r);
  Log log;
  log.set_quiet(true);
  try {
    p.check(log);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "p.json: analyzers[0]: analyzer \"needs_supports\" needs particle column "
                 "\"supports\", which neither the source nor an analyzer before it provides "
                 "(source \"random\")");
  }
}

TEST(PipelineErrors, AnAnalyzersRefusalInFinishNamesTheAnalyzer) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(
      R"({"source": {"plugin": "random", "params": {"frames": 4}},
          "analyzers": [{"plugin": "meanx"}, {"plugin": "refuses_at_the_end"}]})",
      "p.json", {}, r);
  EXPECT_EQ(refusal_of_run(p, "finish_refusal"),
            "p.json: analyzers[1]: expected at least 5 frames, got 4");
}

// A refusal while a sweep ran did not say which point it came from: the value at fault
// could not be told in a long sweep.
TEST(PipelineErrors, ARefusalDuringASweepNamesThePoint) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(
      R"({"source": {"plugin": "random", "params": {"frames": 4}},
          "analyzers": [{"plugin": "refuses_at_the_end"}],
          "sweep": {"parameters": {"source.params.n": [5, 6]}}})",
      "p.json", {}, r);
  EXPECT_EQ(refusal_of_run(p, "sweep_refusal"),
            "p.json: analyzers[0]: expected at least 5 frames, got 4 (sweep point 0: "
            "source.params.n = 5)");
}

// The "report" section is checked with the pipeline: a misspelled plot or column is
// refused before the run, not missing from report.html after it.
TEST(PipelineErrors, ReportSectionNamesWhatItExpected) {
  const std::string sweep = R"(, "sweep": {"parameters": {"source.params.n": [10, 20]}})";
  const auto with_report = [&](const std::string& report, const std::string& more = "") {
    std::string text = kGood;
    text.insert(text.rfind('}'), more + R"(, "report": )" + report);
    return error_of(text);
  };
  EXPECT_EQ(with_report(R"({"papers": []})"),
            "p.json: report.papers: unknown key (did you mean \"paper\"?); known: paper, "
            "sweep_plots, speed_vs_error");
  EXPECT_EQ(
      with_report(R"({"paper": [{"plot": "meany/x", "label": "Fig. 1", "x": [1], "y": [2]}]})"),
      "p.json: report.paper[0].plot: expected \"PRODUCER/NAME\" with PRODUCER one of meanx, "
      "source, got \"meany/x\"");
  EXPECT_EQ(
      with_report(R"({"paper": [{"plot": "meanx/x", "label": "Fig. 1", "x": [1, 2], "y": [2]}]})"),
      "p.json: report.paper[0].y: expected a list of 2 finite numbers, got [2]");
  EXPECT_EQ(with_report(R"({"paper": [{"plot": "meanx/x", "label": "Fig. 1", "x": [1], "y": [2],)"
                        R"( "y_err": [-1]}]})"),
            "p.json: report.paper[0].y_err[0]: expected a finite number >= 0, got -1");
  EXPECT_EQ(with_report(R"({"paper": [{"plot": "meanx/x", "x": [1], "y": [2]}]})"),
            "p.json: report.paper[0].label: expected a value, got null");
  EXPECT_EQ(
      with_report(R"({"speed_vs_error": {"knob": "source.params.n", "time": "source.seconds",)"
                  R"( "quantities": ["meanx.mean_x"]}})"),
      "p.json: report.speed_vs_error.knob: expected a swept parameter, and so a sweep, got "
      "\"source.params.n\"");
  EXPECT_EQ(
      with_report(R"({"speed_vs_error": {"knob": "source.params.frames", "time": "source.seconds",)"
                  R"( "quantities": ["meanx.mean_x"]}})",
                  sweep),
      "p.json: report.speed_vs_error.knob: expected a swept parameter (source.params.n), got "
      "\"source.params.frames\"");
  EXPECT_EQ(
      with_report(R"({"speed_vs_error": {"knob": "source.params.n", "time": "source.seconds",)"
                  R"( "quantities": ["mean_x"]}})",
                  sweep),
      "p.json: report.speed_vs_error.quantities[0]: expected \"PRODUCER.NAME\" with PRODUCER "
      "one of meanx, source, got \"mean_x\"");
  EXPECT_EQ(
      with_report(R"({"speed_vs_error": {"knob": "source.params.n", "time": "source.seconds",)"
                  R"( "quantities": ["meanx.mean_x"]}})",
                  sweep),
      "no error");
  const std::string plot = R"({"name": "mean", "x": "source.params.n", "y": ["meanx.mean_x"]})";
  EXPECT_EQ(with_report(R"({"sweep_plots": [)" + plot + ", " + plot + "]}", sweep),
            "p.json: report.sweep_plots[1].name: expected a name no other sweep plot has, got "
            "\"mean\"");
  const std::string paper = R"(], "paper": [{"label": "Fig. 3", "x": [1], "y": [1], "plot": )";
  EXPECT_EQ(with_report(R"({"sweep_plots": [)" + plot + paper + R"("sweep/means"}]})", sweep),
            "p.json: report.paper[0].plot: expected a plot named in report.sweep_plots, got "
            "\"sweep/means\"");
  EXPECT_EQ(with_report(R"({"sweep_plots": [)" + plot + paper + R"("sweep/mean"}]})", sweep),
            "no error");
}

// Where the time went: one entry per stage, in pipeline order, none longer than the run.
TEST(Pipeline, StageTimesNameEveryStage) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(kGood, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.out = fresh_dir("stages");
  const RunSummary run = p.run(o, log);
  const std::vector<std::string> expected{"source random", "analyzer meanx", "frames file"};
  EXPECT_EQ(run.stage_names, expected);
  ASSERT_EQ(run.stage_seconds.size(), expected.size());
  double sum = 0;
  for (double s : run.stage_seconds) {
    EXPECT_GE(s, 0.0);
    sum += s;
  }
  EXPECT_LE(sum, run.seconds);  // one point: its stages ran one after another
  fs::remove_all(*o.out);
}

TEST(Pipeline, DefaultsAreFilledIn) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(R"({"source": {"plugin": "random"}})", "dir/p.json", {}, r);
  const std::string j = p.resolved_json();
  EXPECT_NE(j.find("\"frames\": 3"), std::string::npos) << j;
  EXPECT_NE(j.find("\"dir\": \"out/p\""), std::string::npos) << j;
  EXPECT_EQ(p.seed(), 1u);
}

// A seed of 1e3 was refused while a plugin's integer parameter took 1e3: whole numbers are
// integers everywhere; the largest seeds, beyond what a double holds exactly, as integers.
TEST(Pipeline, SeedsAreWholeNumbersAsIntegerParametersAre) {
  const Registry r = test_registry();
  const auto seed = [&](const std::string& value) {
    return Pipeline::parse(R"({"seed": )" + value + R"(, "source": {"plugin": "random"}})",
                           "p.json", {}, r)
        .seed();
  };
  EXPECT_EQ(seed("1e3"), 1000u);
  EXPECT_EQ(seed("64.0"), 64u);
  EXPECT_EQ(seed("18446744073709551615"), 18446744073709551615u);
  EXPECT_EQ(error_of(R"({"seed": 1.5, "source": {"plugin": "random"}})"),
            "p.json: seed: expected an integer >= 0, got 1.5");
  EXPECT_EQ(error_of(R"({"seed": 1e19, "source": {"plugin": "random"}})"),
            "p.json: seed: expected an integer >= 0, got 1e+19");
}

// A grid of 3 x 2 points over a source and an analyzer parameter.
constexpr const char* kGrid =
    R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
    "sweep": {"parameters": {"source.params.n": [1, 2, 3], "analyzers[0].params.scale": [1, 2]}}})";

TEST(Pipeline, SweepGridAndZip) {
  const Registry r = test_registry();
  EXPECT_EQ(Pipeline::parse(kGrid, "p.json", {}, r).points(), 6u);
  const char* zip = R"({"source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
    "sweep": {"mode": "zip", "parameters": {"source.params.n": [1, 2], "analyzers[0].params.scale": [1, 2]}}})";
  EXPECT_EQ(Pipeline::parse(zip, "p.json", {}, r).points(), 2u);
}

// A sweep's parameter names are paths: --set sweep.parameters.<path>=[...] replaces that
// parameter's values (it nested objects the sweep refused: "sweep.parameters[\"source\"]:
// expected a non-empty list of values").
TEST(Pipeline, SetIntoASweepReplacesTheValuesOfTheParameterItNames) {
  const Registry r = test_registry();
  EXPECT_EQ(Pipeline::parse(kGrid, "p.json", {"sweep.parameters.source.params.n=[4]"}, r).points(),
            2u);
  EXPECT_EQ(Pipeline::parse(kGrid, "p.json", {"sweep.parameters.analyzers[0].params.scale=[3]"}, r)
                .points(),
            3u);
  EXPECT_EQ(error_of(kGrid, {"sweep.parameters.source.params.n=5"}),
            "--set sweep.parameters.source.params.n=5: expected a non-empty list of values, got 5");
  EXPECT_EQ(
      error_of(kGrid, {"sweep.parameters.x=[1]"}),
      "--set sweep.parameters.x=[1]: expected a plugin parameter path like source.params.name "
      "or analyzers[0].params.name, got \"x\"");
  // The --set's value, not the file's (which was blamed).
  EXPECT_EQ(error_of(kGrid, {"sweep.parameters.source.params.n=[5000]"}),
            "--set sweep.parameters.source.params.n=[5000]: expected an integer in [1, 1000], got "
            "5000 (sweep point 0: analyzers[0].params.scale = 1, source.params.n = 5000)");
}

TEST(Pipeline, SameSeedSameResultsAndSweepPointsIndependentOfThreads) {
  const Registry r = test_registry();
  const char* text =
      R"({"seed": 9, "source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
    "output": {"save_frames": false}, "sweep": {"parameters": {"source.params.n": [10, 20, 30]}}})";
  const Pipeline p = Pipeline::parse(text, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions one, two;
  one.progress = two.progress = false;
  one.threads = 1;
  two.threads = 2;
  one.out = fresh_dir("one");
  two.out = fresh_dir("two");
  const RunSummary a = p.run(one, log), b = p.run(two, log);
  for (const char* k : {"point_000/meanx", "point_001/meanx", "point_002/meanx"}) {
    EXPECT_EQ(a.results.at(k).scalar("mean_x").value, b.results.at(k).scalar("mean_x").value) << k;
  }
  EXPECT_NE(a.results.at("point_000/meanx").scalar("mean_x").value,
            a.results.at("point_001/meanx").scalar("mean_x").value);
  EXPECT_TRUE(fs::exists(*one.out / "results.h5"));
  EXPECT_TRUE(fs::exists(*one.out / "sweep.points.csv"));
  fs::remove_all(*one.out);
  fs::remove_all(*two.out);
}

// "seeds": "shared" gives every point point 0's seeds: points that differ only in a
// parameter the random numbers do not depend on give the same bits.
TEST(Pipeline, SharedSweepSeedsGiveEveryPointTheSameRandomNumbers) {
  const Registry r = test_registry();
  const auto mean_x = [&](const std::string& seeds) {
    const std::string text =
        R"({"seed": 9, "source": {"plugin": "random"}, "analyzers": [{"plugin": "meanx"}],
        "output": {"save_frames": false},
        "sweep": {"seeds": ")" +
        seeds + R"(", "parameters": {"analyzers[0].params.scale": [1, 1]}}})";
    const Pipeline p = Pipeline::parse(text, "p.json", {}, r);
    Log log;
    log.set_quiet(true);
    RunOptions o = quiet_options();
    o.out = fresh_dir("seeds_" + seeds);
    const RunSummary s = p.run(o, log);
    fs::remove_all(*o.out);
    return std::pair(s.results.at("point_000/meanx").scalar("mean_x").value,
                     s.results.at("point_001/meanx").scalar("mean_x").value);
  };
  const auto [shared0, shared1] = mean_x("shared");
  EXPECT_EQ(shared0, shared1);
  const auto [own0, own1] = mean_x("per_point");
  EXPECT_NE(own0, own1);
  EXPECT_EQ(own0, shared0);  // point 0 is the same run either way
  EXPECT_EQ(
      error_of(
          R"({"source": {"plugin": "random"}, "sweep": {"seeds": "same", "parameters": {"source.params.n": [1]}}})"),
      "p.json: sweep.seeds: expected one of \"per_point\", \"shared\", got \"same\"");
}

TEST(Pipeline, SameSeedAndThreadsTwiceGivesTheSameBits) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(kGood, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.threads = 2;
  o.out = fresh_dir("twice_a");
  const double a = p.run(o, log).results.at("meanx").scalar("mean_x").value;
  fs::remove_all(*o.out);
  o.out = fresh_dir("twice_b");
  const double b = p.run(o, log).results.at("meanx").scalar("mean_x").value;
  fs::remove_all(*o.out);
  EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0);
  const Pipeline other_seed = Pipeline::parse(kGood, "p.json", {"seed=6"}, r);
  o.out = fresh_dir("twice_c");
  EXPECT_NE(other_seed.run(o, log).results.at("meanx").scalar("mean_x").value, a);
  fs::remove_all(*o.out);
}

TEST(Pipeline, ExistingOutputDirectoryIsNeverOverwrittenSilently) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(kGood, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.out = fresh_dir("exists");
  fs::create_directories(*o.out);
  std::ofstream(*o.out / "precious.txt") << "mine";
  EXPECT_THROW(p.run(o, log), InputError);
  o.overwrite = true;  // still refused: not a granpipe output directory
  EXPECT_THROW(p.run(o, log), InputError);
  EXPECT_TRUE(fs::exists(*o.out / "precious.txt"));
  fs::remove_all(*o.out);
  o.overwrite = false;
  p.run(o, log);
  EXPECT_THROW(p.run(o, log), InputError);
  o.overwrite = true;
  EXPECT_NO_THROW(p.run(o, log));
  fs::remove_all(*o.out);
}

TEST(Pipeline, SavedFramesReadBackAndCarryProvenance) {
  const Registry r = test_registry();
  const Pipeline p = Pipeline::parse(kGood, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  o.out = fresh_dir("frames");
  p.run(o, log);
  FrameReader reader(*o.out / "frames.h5");
  EXPECT_EQ(reader.frames(), 4);
  EXPECT_TRUE(reader.info().complete);
  EXPECT_FALSE(fs::exists(*o.out / "frames.partial.h5"));
  fs::remove_all(*o.out);
}

// Every frame_stride-th frame is saved, and the last: a run of 375 frames at stride 10 left
// out its final state, the one a continuation starts from.
TEST(Pipeline, AStrideSavesEveryKthFrameAndTheLast) {
  const Registry r = test_registry();
  Log log;
  log.set_quiet(true);
  RunOptions o = quiet_options();
  for (const auto& [frames, saved] :
       {std::pair{5, std::vector<std::int64_t>{0, 3, 4}}, {7, {0, 3, 6}}, {1, {0}}}) {
    const Pipeline p = Pipeline::parse(
        kGood, "p.json",
        {"output.frame_stride=3", "source.params.frames=" + std::to_string(frames)}, r);
    o.out = fresh_dir("stride_" + std::to_string(frames));
    EXPECT_EQ(p.run(o, log).frames, frames);
    FrameReader reader(*o.out / "frames.h5");
    std::vector<std::int64_t> steps;
    for (long k = 0; k < reader.frames(); ++k) steps.push_back(reader.read(k).step);
    EXPECT_EQ(steps, saved) << frames << " frames";
    fs::remove_all(*o.out);
  }
}

TEST(Pipeline, TheSourceIsHandedAnEmptyFrameEveryTime) {
  Registry r = test_registry();
  Schema s;
  s.integer("frames", 3, "frames to emit").min(1);
  r.add_source<WantsAnEmptyFrame>("wants_an_empty_frame", "refuses a frame not emptied", s);
  for (const char* stride : {"output.frame_stride=1", "output.frame_stride=2"}) {
    const Pipeline p = Pipeline::parse(
        R"({"name": "t", "source": {"plugin": "wants_an_empty_frame", "params": {"frames": 5}}})",
        "p.json", {stride}, r);
    EXPECT_EQ(refusal_of_run(p, "empty_frame"), "no error") << stride;
  }
}

// A negative species was read by some plugins (h5md, packing) and refused by others (dem).
TEST(Frame, CheckRefusesANegativeSpecies) {
  Frame f;
  f.resize(2, 2);
  f.radius().setConstant(0.5);
  f.position()(1, 0) = 1.0;
  f.species()[1] = -3;
  try {
    f.check("x.h5: frame 3");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x.h5: frame 3: particle 1 (id 1): expected a species >= 0, got -3");
  }
}

TEST(Frame, CheckNamesInconsistentContacts) {
  Frame f;
  f.resize(2, 2);
  f.radius().setConstant(0.5);
  f.position()(1, 0) = 1.0;
  f.add_contacts(1);
  f.contact_i()[0] = 0;
  f.contact_j()[0] = 2;  // no particle 2
  try {
    f.check("x.h5: frame 3");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "x.h5: frame 3: contact 0: expected particle indices below 2 (or a wall code -2 "
                 "to -8 as second partner), got 0 and 2");
  }
  f.contact_j()[0] = partner::wall(Wall::YLow);
  EXPECT_NO_THROW(f.check("x.h5: frame 3"));
  // A negative number that is no wall's code is not a wall contact.
  f.contact_j()[0] = -100;
  EXPECT_THROW(f.check("x.h5: frame 3"), InputError);
}
