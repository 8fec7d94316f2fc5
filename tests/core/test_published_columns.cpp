// Columns that plugins add: published by an analyzer, seen by the analyzers after it,
// written to frames.h5, read back by the h5md source, and refused before a run when an
// analyzer needs one that nobody provides.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "granpipe/frame_store.hpp"
#include "granpipe/pipeline.hpp"
#include "granpipe/plugin_loader.hpp"
#include "plugin_harness.hpp"
#include "test_files.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

const Property kLabel{"label", Scope::Particle,         ValueType::Integer, 1,
                      "",      "particle index times 3"};

// A fixed frame of 5 particles along x, one per frame.
class LineSource : public Source {
 public:
  explicit LineSource(const PluginContext&) {}
  FrameContent content() const override { return {.dim = 3}; }
  bool next(Frame& f) override {
    if (emitted_ == 2) return false;
    f.resize(5, 3);
    f.container = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(10, 3, 3));
    for (Eigen::Index i = 0; i < 5; ++i) f.position()(i, 0) = 2.0 * static_cast<double>(i);
    f.radius().setConstant(0.5);
    f.step = emitted_++;
    return true;
  }

 private:
  std::int64_t emitted_ = 0;
};

// The line with a contact between neighbours (4 contacts).
class ChainSource : public LineSource {
 public:
  using LineSource::LineSource;
  FrameContent content() const override { return {.dim = 3, .contacts = true}; }
  bool next(Frame& f) override {
    if (!LineSource::next(f)) return false;
    f.add_contacts(4);
    f.contact_i() = IndexArray::LinSpaced(4, 0, 3);
    f.contact_j() = IndexArray::LinSpaced(4, 1, 4);
    return true;
  }
};

const Property kBond{"bond", Scope::Contact, ValueType::Integer, 1, "", "contact row times 10"};

// Publishes a particle column and a contact column: bond = 10 * contact row.
class BondLabeller : public Analyzer {
 public:
  explicit BondLabeller(const PluginContext&) {}
  void consume(const Frame& f, FrameCache&) override {
    particles_ = f.size();
    contacts_ = f.contacts ? f.contacts->rows() : 0;
  }
  void finish(Results&) override {}
  std::vector<Property> publishes() const override { return {kLabel, kBond}; }
  void publish(PropertyTable& columns) override {
    if (columns.scope() == Scope::Contact) {
      columns.get<IndexArray>("bond") = 10 * IndexArray::LinSpaced(contacts_, 0, contacts_ - 1);
    } else {
      columns.get<IndexArray>("label") = IndexArray::Constant(particles_, 1);
    }
  }

 private:
  Eigen::Index particles_ = 0, contacts_ = 0;
};

// Needs the bond column and reports the sum of bonds over all frames it saw.
class BondSum : public Analyzer {
 public:
  explicit BondSum(const PluginContext&) {}
  FrameContent needs() const override { return {.contacts = true, .columns = {kBond}}; }
  void consume(const Frame& f, FrameCache&) override {
    sum_ += f.contacts->get<IndexArray>("bond").sum();
  }
  void finish(Results& r) override { r.add_scalar("label_sum", static_cast<double>(sum_)); }

 private:
  std::int64_t sum_ = 0;
};

// Publishes label = 3 * index, computed in consume as a real analyzer would.
class Labeller : public Analyzer {
 public:
  explicit Labeller(const PluginContext&) {}
  void consume(const Frame& f, FrameCache&) override {
    labels_ = 3 * IndexArray::LinSpaced(f.size(), 0, f.size() - 1);
  }
  void finish(Results&) override {}
  std::vector<Property> publishes() const override { return {kLabel}; }
  void publish(PropertyTable& columns) override { columns.get<IndexArray>("label") = labels_; }

 private:
  IndexArray labels_;
};

const Property kPressure{"pressure", Scope::Frame, ValueType::Real, 1, "", "a per-frame value"};

// Declares an observable, which analyzers cannot publish.
class ObservableLabeller : public Labeller {
 public:
  using Labeller::Labeller;
  std::vector<Property> publishes() const override { return {kLabel, kPressure}; }
};

// Needs the label column and reports the sum of labels over all frames it saw.
class LabelSum : public Analyzer {
 public:
  explicit LabelSum(const PluginContext&) {}
  FrameContent needs() const override { return {.columns = {kLabel}}; }
  void consume(const Frame& f, FrameCache&) override { sum_ += f.get<std::int64_t>("label").sum(); }
  void finish(Results& r) override { r.add_scalar("label_sum", static_cast<double>(sum_)); }

 private:
  std::int64_t sum_ = 0;
};

// Declares label but never fills it.
class LazyLabeller : public Labeller {
 public:
  using Labeller::Labeller;
  void publish(PropertyTable&) override {}
};

// Fills label with too few rows.
class ShortLabeller : public Labeller {
 public:
  using Labeller::Labeller;
  void publish(PropertyTable& columns) override {
    columns.get<IndexArray>("label") = IndexArray::Zero(3);
  }
};

// Fills label through add(), which hands out the declared column.
class AddingLabeller : public Labeller {
 public:
  using Labeller::Labeller;
  void publish(PropertyTable& columns) override {
    columns.add<IndexArray>(kLabel) = 3 * IndexArray::LinSpaced(5, 0, 4);
  }
};

// Fills a column it did not declare (a typo).
class TypoLabeller : public Labeller {
 public:
  using Labeller::Labeller;
  void publish(PropertyTable& columns) override {
    columns.get<IndexArray>("lable") = IndexArray::Zero(5);
  }
};

// Needs label as a real column, and a column nobody provides under a near name.
const Property kRealLabel{"label", Scope::Particle, ValueType::Real, 1, "", "label as a real"};
class RealLabelReader : public LabelSum {
 public:
  using LabelSum::LabelSum;
  FrameContent needs() const override { return {.columns = {kRealLabel}}; }
};
class MisspeltLabelReader : public LabelSum {
 public:
  using LabelSum::LabelSum;
  FrameContent needs() const override {
    return {.columns = {{"lable", Scope::Particle, ValueType::Integer, 1, "", ""}}};
  }
};

// The line with label as a real column, as frames of another tool might carry it.
class RealLabelledLine : public LineSource {
 public:
  using LineSource::LineSource;
  FrameContent content() const override { return {.dim = 3, .columns = {kRealLabel}}; }
  bool next(Frame& f) override {
    if (!LineSource::next(f)) return false;
    f.particles.add(kRealLabel);
    return true;
  }
};

// Publishes velocity as an integer: not the standard column's type.
class IntegerVelocity : public Labeller {
 public:
  using Labeller::Labeller;
  std::vector<Property> publishes() const override {
    return {{"velocity", Scope::Particle, ValueType::Integer, 1, "", ""}};
  }
};

Registry registry_with_h5md() {
  Registry r;
  load_plugins(r, plugin_search_path());  // the real h5md source
  r.add_source<LineSource>("line", "five particles on a line", Schema{});
  r.add_analyzer<Labeller>("labeller", "publishes label", Schema{});
  r.add_analyzer<ObservableLabeller>("observable_labeller", "publishes label and pressure",
                                     Schema{});
  r.add_analyzer<LabelSum>("label_sum", "sums label", Schema{});
  r.add_source<ChainSource>("chain", "five particles on a line, neighbours in contact", Schema{});
  r.add_analyzer<BondLabeller>("bond_labeller", "publishes label and bond", Schema{});
  r.add_analyzer<BondSum>("bond_sum", "sums bond", Schema{});
  r.add_analyzer<LazyLabeller>("lazy_labeller", "declares label, never fills it", Schema{});
  r.add_analyzer<ShortLabeller>("short_labeller", "fills label with 3 rows", Schema{});
  r.add_analyzer<TypoLabeller>("typo_labeller", "fills lable", Schema{});
  r.add_analyzer<AddingLabeller>("adding_labeller", "fills label through add()", Schema{});
  r.add_analyzer<RealLabelReader>("real_label_reader", "needs label as real", Schema{});
  r.add_analyzer<MisspeltLabelReader>("misspelt_label_reader", "needs lable", Schema{});
  r.add_source<RealLabelledLine>("real_labelled_line", "the line with a real label", Schema{});
  r.add_analyzer<IntegerVelocity>("integer_velocity", "publishes velocity as an integer", Schema{});
  return r;
}

fs::path fresh_dir(const std::string& name) { return test::fresh_path("columns", name); }

double run_label_sum(const std::string& text, const Registry& r, const fs::path& out) {
  const Pipeline p = Pipeline::parse(text, "p.json", {}, r);
  Log log;
  log.set_quiet(true);
  RunOptions o;
  o.progress = false;
  o.out = out;
  return p.run(o, log).results.at("label_sum").scalar("label_sum").value;
}

// The message of a pipeline of the line source (or `source`) and these analyzers refused
// by check().
std::string refusal_of(const std::string& analyzers, const std::string& source = "line") {
  const Registry r = registry_with_h5md();
  const Pipeline p = Pipeline::parse(
      R"({"source": {"plugin": ")" + source + R"("}, "analyzers": )" + analyzers + "}", "p.json",
      {}, r);
  Log log;
  log.set_quiet(true);
  try {
    p.check(log);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(PublishedColumns, SeenByLaterAnalyzersWrittenAndReadBackByTheH5mdSource) {
  const Registry r = registry_with_h5md();
  const fs::path first = fresh_dir("first"), second = fresh_dir("second");
  // 2 frames x (0 + 3 + 6 + 9 + 12)
  EXPECT_EQ(run_label_sum(R"({"source": {"plugin": "line"},
      "analyzers": [{"plugin": "labeller"}, {"plugin": "label_sum"}]})",
                          r, first),
            60.0);

  FrameReader saved(first / "frames.h5");
  ASSERT_TRUE(saved.info().has("label"));
  const Frame f = saved.read(1);
  EXPECT_EQ(f.get<std::int64_t>("label")[4], 12);
  EXPECT_EQ(f.particles.find("label")->property().doc, kLabel.doc);

  const std::string reprocess = R"({"source": {"plugin": "h5md", "params": {"file": ")" +
                                (first / "frames.h5").string() +
                                R"("}}, "analyzers": [{"plugin": "label_sum"}]})";
  EXPECT_EQ(run_label_sum(reprocess, r, second), 60.0);

  // Reprocessed by the analyzer that made the column: its new values replace the saved ones.
  const fs::path third = fresh_dir("third");
  const std::string again =
      R"({"source": {"plugin": "h5md", "params": {"file": ")" + (first / "frames.h5").string() +
      R"("}}, "analyzers": [{"plugin": "labeller"}, {"plugin": "label_sum"}]})";
  EXPECT_EQ(run_label_sum(again, r, third), 60.0);
  std::ifstream log(third / "run.log");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(
      text.find(
          "warning: p.json: analyzers[0]: analyzer \"labeller\" replaces the particle column "
          "\"label\" that the source \"h5md\" provides (an earlier run's, read back) with its own"),
      std::string::npos)
      << text;
  fs::remove_all(third);
  fs::remove_all(first);
  fs::remove_all(second);
}

TEST(PublishedColumns, PipelineOrderDecidesWhoSeesAColumn) {
  EXPECT_EQ(refusal_of(R"([{"plugin": "label_sum"}, {"plugin": "labeller"}])"),
            "p.json: analyzers[0]: analyzer \"label_sum\" needs particle column \"label\", which "
            "neither the source nor an analyzer before it provides (source \"line\")");
}

// The message of a run of the line source and these analyzers that stops with an InputError.
std::string run_error_of(const std::string& analyzers, const std::string& name) {
  const Registry r = registry_with_h5md();
  const fs::path out = fresh_dir(name);
  const std::string message = test::input_error_of([&] {
    run_label_sum(R"({"source": {"plugin": "line"}, "analyzers": )" + analyzers + "}", r, out);
  });
  fs::remove_all(out);
  return message;
}

TEST(PublishedColumns, AColumnPublishedTwiceIsRefusedNamingBothPublishers) {
  EXPECT_EQ(
      refusal_of(R"([{"plugin": "labeller"}, {"plugin": "labeller", "name": "again"}])"),
      "p.json: analyzers[1]: analyzer \"again\" (labeller) publishes the particle column "
      "\"label\", which analyzer \"labeller\" at analyzers[0] publishes too; give one of them "
      "\"publish\": false (docs/pipelines.md, \"Published columns\")");
}

TEST(PublishedColumns, ASecondInstanceWithPublishFalseRunsAndLeavesTheColumnToTheFirst) {
  const Registry r = registry_with_h5md();
  const fs::path out = fresh_dir("publish_false");
  EXPECT_EQ(run_label_sum(R"({"source": {"plugin": "line"},
      "analyzers": [{"plugin": "labeller"}, {"plugin": "short_labeller", "publish": false},
                    {"plugin": "label_sum"}]})",
                          r, out),
            60.0);
  fs::remove_all(out);
  try {
    Pipeline::parse(
        R"({"source": {"plugin": "line"}, "analyzers": [{"plugin": "labeller", "publish": 1}]})",
        "p.json", {}, r);
    ADD_FAILURE() << "\"publish\": 1 was accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "p.json: analyzers[0].publish: expected true or false, got 1");
  }
}

TEST(PublishedColumns, AColumnOfAnotherTypeThanTheSourcesOrTheStandardOneIsRefused) {
  EXPECT_EQ(refusal_of(R"([{"plugin": "labeller"}])", "real_labelled_line"),
            "p.json: analyzers[0]: analyzer \"labeller\" publishes the particle column \"label\" "
            "as integer, "
            "but the source \"real_labelled_line\" provides it as real: choose another name");
  EXPECT_EQ(refusal_of(R"([{"plugin": "integer_velocity"}])"),
            "p.json: analyzers[0]: analyzer \"integer_velocity\" publishes the particle column "
            "\"velocity\" "
            "as integer, but the standard column of that name is real[dim]: choose another name");
}

TEST(PublishedColumns, ANeededTypeMismatchNamesThePublisher) {
  EXPECT_EQ(refusal_of(R"([{"plugin": "labeller"}, {"plugin": "real_label_reader"}])"),
            "p.json: analyzers[1]: analyzer \"real_label_reader\" needs particle column \"label\" "
            "as real, "
            "but analyzer \"labeller\" at analyzers[0] publishes it as integer");
  EXPECT_EQ(refusal_of(R"([{"plugin": "real_label_reader"}])", "real_labelled_line"), "no error");
}

TEST(PublishedColumns, ANeededColumnNameGetsADidYouMean) {
  EXPECT_EQ(
      refusal_of(R"([{"plugin": "labeller"}, {"plugin": "misspelt_label_reader"}])"),
      "p.json: analyzers[1]: analyzer \"misspelt_label_reader\" needs particle column \"lable\" "
      "(did you mean \"label\"?), which neither the source nor an analyzer before it provides "
      "(source \"line\")");
}

TEST(PublishedColumns, AColumnPublishNeverFilledStopsTheRunInsteadOfSavingZeros) {
  EXPECT_EQ(run_error_of(R"([{"plugin": "lazy_labeller"}, {"plugin": "label_sum"}])", "lazy"),
            "p.json: analyzers[0]: analyzer \"lazy_labeller\": publish() never filled the particle "
            "column "
            "\"label\" it declares");
}

TEST(PublishedColumns, AColumnFilledThroughAddCountsAsFilled) {
  const Registry r = registry_with_h5md();
  const fs::path out = fresh_dir("adding");
  EXPECT_EQ(run_label_sum(R"({"source": {"plugin": "line"},
      "analyzers": [{"plugin": "adding_labeller"}, {"plugin": "label_sum"}]})",
                          r, out),
            60.0);
  fs::remove_all(out);
}

TEST(PublishedColumns, PublishErrorsNameTheAnalyzerTheColumnAndTheSizes) {
  EXPECT_EQ(run_error_of(R"([{"plugin": "short_labeller"}, {"plugin": "label_sum"}])", "short"),
            "p.json: analyzers[0]: analyzer \"short_labeller\": publish() gave the particle column "
            "\"label\" "
            "3 rows x 1 component, expected 5 rows x 1 component (one row per particle)");
  EXPECT_EQ(run_error_of(R"([{"plugin": "typo_labeller"}, {"plugin": "label_sum"}])", "typo"),
            "p.json: analyzers[0]: analyzer \"typo_labeller\": publish(): the particle table has "
            "no column "
            "\"lable\" (did you mean \"label\"?); known: label; publish() fills only the columns "
            "publishes() "
            "declares");
}

TEST(PublishedColumns, AFrameColumnCannotBePublished) {
  EXPECT_EQ(refusal_of(R"([{"plugin": "observable_labeller"}])"),
            "p.json: analyzers[0]: analyzer \"observable_labeller\" publishes the frame column "
            "\"pressure\": expected particle or contact columns only");
}

TEST(PublishedColumns, ContactColumnsJoinTheContactTableAndAreWritten) {
  const Registry r = registry_with_h5md();
  const fs::path out = fresh_dir("contacts");
  // 2 frames x (0 + 10 + 20 + 30)
  EXPECT_EQ(run_label_sum(R"({"source": {"plugin": "chain"},
      "analyzers": [{"plugin": "bond_labeller"}, {"plugin": "bond_sum", "name": "label_sum"}]})",
                          r, out),
            120.0);
  FrameReader saved(out / "frames.h5");
  const Frame f = saved.read(1);
  ASSERT_TRUE(f.contacts && f.contacts->has("bond"));
  EXPECT_EQ(f.contacts->get<IndexArray>("bond")[3], 30);
  EXPECT_EQ(f.get<std::int64_t>("label")[4], 1);
  fs::remove_all(out);
}

TEST(PublishedColumns, ContactColumnsAreLeftOutOfFramesWithoutContacts) {
  const Registry r = registry_with_h5md();
  const fs::path out = fresh_dir("no_contacts");
  // The particle column is published; the contact column has no table to join.
  EXPECT_EQ(run_label_sum(R"({"source": {"plugin": "line"},
      "analyzers": [{"plugin": "bond_labeller"}, {"plugin": "label_sum"}]})",
                          r, out),
            10.0);
  FrameReader saved(out / "frames.h5");
  EXPECT_FALSE(saved.read(0).contacts.has_value());
  fs::remove_all(out);
}

// Issue 18, point 13: packing measured in two regions, as pipelines of earlier versions did.
TEST(PublishedColumns, TwoPackingAnalyzersMeasureTwoRegionsInTheirOwnGroups) {
  Registry r;
  load_plugins(r, plugin_search_path());
  const std::string source =
      R"({"source": {"plugin": "lattice", "params": {"lattice": "fcc", "cells": [4, 4, 8],
      "boundary": "walls", "jitter": 0.05, "frames": 2}}, "analyzers": [
      {"plugin": "packing", "name": "lower", "params": {"exclude_top": 4, "contact_tolerance": 0.11}},
      {"plugin": "packing", "name": "upper", )";
  const std::string upper = R"("params": {"exclude_bottom": 4, "contact_tolerance": 0.11}}]})";
  Log log;
  log.set_quiet(true);
  try {
    Pipeline::parse(source + upper, "p.json", {}, r).check(log);
    ADD_FAILURE() << "two packing analyzers that both publish coordination were accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "p.json: analyzers[1]: analyzer \"upper\" (packing) publishes the particle "
        "column \"coordination\", which analyzer \"lower\" (packing) at analyzers[0] "
        "publishes too; give one of them \"publish\": false (docs/pipelines.md, \"Published "
        "columns\")");
  }

  const Pipeline p = Pipeline::parse(source + R"("publish": false, )" + upper, "p.json", {}, r);
  RunOptions o;
  o.progress = false;
  o.out = fresh_dir("two_packings");
  const ResultSet results = p.run(o, log).results;
  const double lower = results.at("lower").scalar("phi").value,
               top = results.at("upper").scalar("phi").value;
  // Jitter 0.05 shrinks the radii of the fcc crystal (0.74) by 5 %: about 0.56.
  EXPECT_GT(lower, 0.5);
  EXPECT_LT(lower, 0.65);
  EXPECT_GT(top, 0.5);
  EXPECT_LT(top, 0.65);
  EXPECT_NE(lower, top);  // two regions of one jittered crystal
  EXPECT_TRUE(FrameReader(*o.out / "frames.h5").info().has("coordination"));
  fs::remove_all(*o.out);
}
