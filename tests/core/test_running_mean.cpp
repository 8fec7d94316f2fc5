// Running means: Welford's update and the batched one agree with the two-pass formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "granpipe/results.hpp"

using namespace granpipe;

TEST(RunningMean, MatchesTwoPassMeanAndStandardError) {
  const std::vector<double> x{0.81, 0.83, 0.80, 0.84, 0.82, 0.85};
  RunningMean m;
  for (double v : x) m.add(v);
  double mean = 0, var = 0;
  for (double v : x) mean += v / x.size();
  for (double v : x) var += (v - mean) * (v - mean) / (x.size() - 1);
  EXPECT_NEAR(m.mean(), mean, 1e-15);
  EXPECT_NEAR(m.variance(), var, 1e-15);
  EXPECT_NEAR(m.standard_error(), std::sqrt(var / x.size()), 1e-15);
}

TEST(RunningMean, BatchedAddEqualsRepeatedAdd) {
  RunningMean one_by_one, batched;
  for (double v : {0.3, 0.5}) {
    one_by_one.add(v);
    batched.add(v);
  }
  for (int k = 0; k < 7; ++k) one_by_one.add(0.0);
  batched.add(0.0, 7);
  batched.add(0.0, 0);  // nothing
  EXPECT_EQ(batched.count(), one_by_one.count());
  EXPECT_NEAR(batched.mean(), one_by_one.mean(), 1e-15);
  EXPECT_NEAR(batched.variance(), one_by_one.variance(), 1e-15);
  RunningMean from_empty;
  from_empty.add(2.0, 3);
  EXPECT_EQ(from_empty.mean(), 2.0);
  EXPECT_EQ(from_empty.variance(), 0.0);
}
