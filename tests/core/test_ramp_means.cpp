// Per-(branch, time) means of a ramped run: the first increase stays apart, later
// increasing and decreasing ramps pool over their cycles, frames without a cycle are ignored.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/ramp_means.hpp"

using namespace granpipe;

namespace {
Frame at(std::int64_t cycle, double amplitude) {
  Frame f;
  f.set_observable({"cycle", Scope::Frame, ValueType::Integer, 1, "", ""}, cycle);
  f.set_observable({"amplitude", Scope::Frame, ValueType::Real, 1, "", ""}, amplitude);
  return f;
}
}  // namespace

TEST(RampMeans, BranchesOfHalfCycles) {
  EXPECT_EQ(ramp_branch(0), RampBranch::FirstIncrease);
  EXPECT_EQ(ramp_branch(1), RampBranch::Decreasing);
  EXPECT_EQ(ramp_branch(2), RampBranch::Increasing);
  EXPECT_EQ(ramp_branch(3), RampBranch::Decreasing);
}

TEST(RampMeans, GroupsByBranchAndTime) {
  RampMeans m({"phi"});
  m.add(at(0, 1.1), {0.80});
  m.add(at(0, 1.1), {0.82});   // the first rise: kept apart
  m.add(at(1, 1.1), {0.84});   // decreasing, first cycle
  m.add(at(3, 1.1), {0.86});   // decreasing, second cycle: pooled with it
  m.add(at(2, 1.1), {0.83});   // a later increase: its own branch
  m.add(at(-1, 1.1), {0.10});  // no cycle: not part of any branch
  const Table t = m.table("doc");
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.column("branch"), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(t.column("frames"), (std::vector<double>{2, 2, 1}));
  EXPECT_DOUBLE_EQ(t.column("phi")[0], 0.81);
  EXPECT_NEAR(t.column("phi_err")[0], 0.01, 1e-15);  // sd 0.01414 / sqrt(2)
  EXPECT_DOUBLE_EQ(t.column("phi")[1], 0.85);
  EXPECT_DOUBLE_EQ(t.column("phi")[2], 0.83);
}

TEST(RampMeans, EmptyWithoutCycles) {
  RampMeans m({"phi", "z"});
  m.add(at(-1, 0.0), {1.0, 2.0});
  EXPECT_TRUE(m.empty());
  EXPECT_THROW(RampMeans({"phi"}).add(at(0, 1.0), {1.0, 2.0}), InternalError);
}

// One frame whose phi_b is undefined (a layer too thin for it) made its whole row NaN,
// where the scalar means leave it out: its frame counts, its value does not.
TEST(RampMeans, AnUndefinedValueIsLeftOutOfItsMeanOnly) {
  RampMeans m({"phi_b", "z"});
  m.add(at(0, 1.1), {0.5, 4.0});
  m.add(at(0, 1.1), {std::nan(""), 4.5});
  m.add(at(1, 1.1), {std::nan(""), 5.0});
  const Table t = m.table("doc");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.column("frames"), (std::vector<double>{2, 1}));
  EXPECT_EQ(t.column("phi_b")[0], 0.5);
  EXPECT_DOUBLE_EQ(t.column("z")[0], 4.25);
  EXPECT_TRUE(std::isnan(t.column("phi_b")[1]));  // defined in no frame: undefined, not 0
  EXPECT_EQ(t.column("z")[1], 5.0);
}
