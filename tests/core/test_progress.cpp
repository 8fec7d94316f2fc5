// Progress off a terminal (as in CI and logs): plain lines, the last one complete.
#include <gtest/gtest.h>

#include "granpipe/progress.hpp"

using namespace granpipe;

TEST(Progress, PlainFinalLineWithCountAndRate) {
  Progress p;
  testing::internal::CaptureStderr();
  p.start("demo", 4, "taps");
  for (int k = 0; k < 4; ++k) p.advance();
  p.finish();
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_NE(out.find("demo: 4/4 taps (100.0%)"), std::string::npos) << out;
  EXPECT_NE(out.find("taps/s"), std::string::npos) << out;
  EXPECT_NE(out.find("ETA done"), std::string::npos) << out;
  EXPECT_EQ(out.find('\r'), std::string::npos) << "no bar redraws off a terminal";
  EXPECT_EQ(p.done(), 4.0);
}

// An interrupted run's last line said "ETA done" at 0/2 taps.
TEST(Progress, AnIncompleteRunsLastLineSaysSo) {
  Progress p;
  testing::internal::CaptureStderr();
  p.start("cut", 4, "taps");
  p.advance();
  p.finish(false);
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_NE(out.find("cut: 1/4 taps (25.0%)"), std::string::npos) << out;
  EXPECT_NE(out.find("ETA stopped short\n"), std::string::npos) << out;
}

TEST(Progress, DisabledPrintsNothingButCounts) {
  Progress p;
  p.set_enabled(false);
  testing::internal::CaptureStderr();
  p.start("quiet", 2, "frames");
  p.advance(2);
  p.finish();
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(p.done(), 2.0);
}

TEST(Progress, TheSourcesStatusFollowsTheFigures) {
  Progress p;
  testing::internal::CaptureStderr();
  p.start("dem", 10, "steps");
  p.set_status("t = 1.00, cycle 0.11, 2e+07 particle-steps/s");
  p.advance(10);
  p.finish();
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_NE(out.find("ETA done, t = 1.00, cycle 0.11, 2e+07 particle-steps/s\n"), std::string::npos)
      << out;
}

TEST(Progress, SkippedWorkCountsAsDoneButNotInTheRate) {
  Progress p;
  testing::internal::CaptureStderr();
  p.start("continued", 4000, "taps");
  p.skip(3550);
  p.advance(450);
  p.finish();
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_NE(out.find("continued: 4000/4000 taps (100.0%)"), std::string::npos) << out;
  EXPECT_EQ(p.done(), 450.0) << "done() counts this run's work only";
}
