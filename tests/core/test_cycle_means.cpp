// Per-(cycle, time) means: rising and falling branches of an annealing run stay apart,
// repeated visits of the same (cycle, time) average together, frames without a cycle
// are ignored.
#include <gtest/gtest.h>

#include "granpipe/cycle_means.hpp"
#include "granpipe/errors.hpp"

using namespace granpipe;

namespace {
Frame at(std::int64_t cycle, double time) {
  Frame f;
  f.cycle = cycle;
  f.time = time;
  return f;
}
}  // namespace

TEST(CycleMeans, GroupsByCycleAndTime) {
  CycleMeans m({"phi"});
  m.add(at(0, 1.1), {0.80});
  m.add(at(0, 1.1), {0.82});  // same step of the first rise: averaged
  m.add(at(1, 1.1), {0.84});  // same A on the falling branch: its own row
  m.add(at(0, 1.2), {0.79});
  m.add(at(-1, 1.1), {0.10});  // no cycle: not part of any branch
  const Table t = m.table("doc");
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.column("cycle"), (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(t.column("time"), (std::vector<double>{1.1, 1.2, 1.1}));
  EXPECT_EQ(t.column("frames"), (std::vector<double>{2, 1, 1}));
  EXPECT_DOUBLE_EQ(t.column("phi")[0], 0.81);
  EXPECT_NEAR(t.column("phi_err")[0], 0.01, 1e-15);  // sd 0.01414 / sqrt(2)
  EXPECT_DOUBLE_EQ(t.column("phi")[2], 0.84);
}

TEST(CycleMeans, EmptyWithoutCycles) {
  CycleMeans m({"phi", "z"});
  m.add(at(-1, 0.0), {1.0, 2.0});
  EXPECT_TRUE(m.empty());
  EXPECT_THROW(CycleMeans({"phi"}).add(at(0, 1.0), {1.0, 2.0}), InternalError);
}
