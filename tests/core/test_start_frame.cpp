// The saved frame a source starts from (read_start_frame): the frame asked for, and each
// refusal in one line naming the parameter at fault.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "granpipe/frame_store.hpp"
#include "granpipe/start_frame.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
namespace fs = std::filesystem;

namespace {

Schema start_schema() {
  Schema s;
  s.path("initial_file", std::string(""), "file to start from");
  s.integer("initial_frame", -1, "its frame (-1: the last)").min(-1);
  return s;
}

// Frames of one sphere at height 1, 2, ... with steps 10, 20, ...
fs::path saved_file(const std::string& name, int frames) {
  const fs::path p =
      fs::temp_directory_path() / ("granpipe_start_frame_" + std::to_string(getpid()) + name);
  fs::remove(p);
  FrameWriter w(p, "{}");
  for (int k = 1; k <= frames; ++k) {
    Frame f;
    f.resize(1, 3);
    f.radius().setConstant(0.5);
    f.position().row(0) << 1.0, 1.0, static_cast<double>(k);
    f.step = 10 * k;
    f.container = Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 2, 9));
    w.append(f);
  }
  w.close();
  return p;
}

std::optional<StartFrame> start(const nlohmann::json& params) {
  return read_start_frame(*test::make_context(start_schema(), params));
}

std::string refusal(const nlohmann::json& params) {
  return test::input_error_of([&] { start(params); });
}

}  // namespace

TEST(StartFrame, NoFileNoStart) { EXPECT_FALSE(start({})); }

TEST(StartFrame, TheFrameAskedForAndTheLastByDefault) {
  const fs::path p = saved_file("three.h5", 3);
  const auto last = start({{"initial_file", p.string()}});
  ASSERT_TRUE(last);
  EXPECT_EQ(last->index, 2);
  EXPECT_EQ(last->frame.step, 30);
  EXPECT_EQ(last->frame.position()(0, 2), 3.0);
  EXPECT_EQ(last->where, "params.initial_file: " + p.string() + ": frame 2");
  const auto first = start({{"initial_file", p.string()}, {"initial_frame", 0}});
  ASSERT_TRUE(first);
  EXPECT_EQ(first->frame.step, 10);
  fs::remove(p);
}

TEST(StartFrame, AFrameWithoutAFileIsRefused) {
  EXPECT_EQ(refusal({{"initial_frame", 0}}),
            "params.initial_frame: expected it only with initial_file (a frame of that file), "
            "got 0 without one");
}

TEST(StartFrame, AFramePastTheLastIsRefused) {
  const fs::path p = saved_file("two.h5", 2);
  EXPECT_EQ(refusal({{"initial_file", p.string()}, {"initial_frame", 2}}),
            "params.initial_frame: expected -1 or a frame index below 2 (" + p.string() +
                " holds 2 frames), got 2");
  fs::remove(p);
}

TEST(StartFrame, AFileWithoutFramesIsRefused) {
  const fs::path p = saved_file("none.h5", 0);
  EXPECT_EQ(refusal({{"initial_file", p.string()}}),
            "params.initial_file: " + p.string() + ": expected a file with frames, got none");
  fs::remove(p);
}

TEST(StartFrame, AFileOfAnotherFormatIsRefusedNamingTheParameter) {
  const fs::path p =
      fs::temp_directory_path() / ("granpipe_start_frame_" + std::to_string(getpid()) + ".txt");
  std::ofstream(p) << "not HDF5\n";
  const std::string message = refusal({{"initial_file", p.string()}});
  EXPECT_EQ(message.rfind("params.initial_file: " + p.string() + ": ", 0), 0u) << message;
  fs::remove(p);
}
