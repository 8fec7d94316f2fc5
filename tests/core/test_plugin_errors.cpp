// Errors a plugin raises while a pipeline runs name where they come from exactly once,
// and a registry never drops a plugin silently.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "granpipe/pipeline.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

class OnePoint : public Source {
 public:
  explicit OnePoint(const PluginContext&) {}
  FrameContent content() const override { return {.dim = 3}; }
  bool next(Frame& f) override {
    if (done_) return false;
    f.resize(1, 3);
    f.radius().setConstant(0.5);
    f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones() * 2);
    f.position().setConstant(1.0);
    return done_ = true;
  }

 private:
  bool done_ = false;
};

// Complains about its parameter from consume, as a plugin that checks data against it.
class RangeTooShort : public Analyzer {
 public:
  explicit RangeTooShort(const PluginContext& ctx) : r_max_(ctx.param("r_max")) {}
  void consume(const Frame&, FrameCache&) override {
    throw InputError(r_max_ + ": expected at least one particle diameter, got 0.1");
  }
  void finish(Results&) override {}

 private:
  std::string r_max_;
};

// Complains about the frame, without naming a parameter.
class NoContacts : public Analyzer {
 public:
  explicit NoContacts(const PluginContext&) {}
  void consume(const Frame&, FrameCache&) override {
    throw InputError("frame 0: expected contacts, got none");
  }
  void finish(Results&) override {}
};

std::string run_error(const std::string& analyzer) {
  Registry r;
  r.add_source<OnePoint>("one", "one particle", Schema{});
  Schema s;
  s.real("r_max", 0.1, "range");
  r.add_analyzer<RangeTooShort>("short_range", "complains about r_max", s);
  r.add_analyzer<NoContacts>("no_contacts", "complains about the frame", Schema{});
  const Pipeline p = Pipeline::parse(
      R"({"source": {"plugin": "one"}, "analyzers": [{"plugin": ")" + analyzer + R"("}]})",
      "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o;
  o.progress = false;
  // A folder per analyzer, removed after: a failed run marks its folder, which a second
  // run into it would find (both tests share one process when the binary runs alone).
  const fs::path out = fs::temp_directory_path() / ("granpipe_test_plugin_errors_" +
                                                    std::to_string(::getpid()) + "_" + analyzer);
  o.out = out;
  const std::string message = test::input_error_of([&] { p.run(o, log); });
  fs::remove_all(out);
  return message;
}

}  // namespace

TEST(PluginErrors, AnErrorAboutAParameterNamesItsPathOnce) {
  EXPECT_EQ(run_error("short_range"),
            "p.json: analyzers[0].params.r_max: expected at least one particle diameter, got 0.1");
}

TEST(PluginErrors, AnErrorAboutTheDataNamesTheAnalyzer) {
  EXPECT_EQ(run_error("no_contacts"), "p.json: analyzers[0]: frame 0: expected contacts, got none");
}

TEST(PluginErrors, APluginRegisteredTwiceInOneRegistryIsAnError) {
  Registry r;
  r.add_source<OnePoint>("one", "one particle", Schema{});
  EXPECT_THROW(r.add_source<OnePoint>("one", "again", Schema{}), InternalError);
}
