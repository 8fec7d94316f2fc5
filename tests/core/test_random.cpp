// Seeded streams: same seed and name give the same bits; names and indices give
// different, uncorrelated streams; uniform() has the right moments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "granpipe/random.hpp"

using namespace granpipe;

TEST(Random, SameSeedSameBits) {
  RandomStream a = Seeds(42).stream("tap", 3), b = Seeds(42).stream("tap", 3);
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(a.bits(), b.bits());
}

TEST(Random, NamesIndicesAndSeedsGiveDifferentStreams) {
  const std::uint64_t x = Seeds(42).stream("tap", 3).bits();
  EXPECT_NE(x, Seeds(42).stream("tap", 4).bits());
  EXPECT_NE(x, Seeds(42).stream("tab", 3).bits());
  EXPECT_NE(x, Seeds(43).stream("tap", 3).bits());
  EXPECT_NE(Seeds(1).derive("point", 0).seed(), Seeds(1).derive("point", 1).seed());
}

TEST(Random, UniformMomentsAndRange) {
  RandomStream r = Seeds(7).stream("moments");
  const int n = 200000;
  double s = 0, s2 = 0;
  for (int k = 0; k < n; ++k) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  // Mean 1/2 and variance 1/12, within 5 standard errors.
  EXPECT_NEAR(s / n, 0.5, 5 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12, 5 * 0.0745 / std::sqrt(n));
}

TEST(Random, BelowIsUniformOverSmallRange) {
  RandomStream r = Seeds(9).stream("below");
  int counts[3] = {0, 0, 0};
  const int n = 30000;
  for (int k = 0; k < n; ++k) ++counts[r.below(3)];
  for (int c : counts) EXPECT_NEAR(c, n / 3.0, 5 * std::sqrt(n * (1.0 / 3) * (2.0 / 3)));
}

TEST(Random, NormalMoments) {
  RandomStream r = Seeds(11).stream("normal");
  const int n = 200000;
  double s = 0, s2 = 0;
  for (int k = 0; k < n; ++k) {
    const double g = r.normal();
    s += g;
    s2 += g * g;
  }
  EXPECT_NEAR(s / n, 0.0, 5 / std::sqrt(n));
  EXPECT_NEAR(s2 / n, 1.0, 5 * std::sqrt(2.0 / n));
}

TEST(Random, ShufflesAreUniformPermutations) {
  // All 6 orders of 3 disks, equally often: chi-square with 5 degrees of freedom stays
  // below 20.5 (p = 0.001) for an unbiased shuffle.
  RandomStream rng(13);
  std::map<std::vector<std::int32_t>, int> seen;
  const int trials = 60000;
  for (int t = 0; t < trials; ++t) {
    std::vector<std::int32_t> v{0, 1, 2};
    rng.shuffle(v);
    ++seen[v];
  }
  ASSERT_EQ(seen.size(), 6u);
  double chi2 = 0;
  for (const auto& [order, count] : seen)
    chi2 += std::pow(count - trials / 6.0, 2) / (trials / 6.0);
  EXPECT_LT(chi2, 20.5);
  std::vector<int> hits(7, 0);
  for (int t = 0; t < 70000; ++t) ++hits[rng.below(7)];
  chi2 = 0;
  for (int h : hits) chi2 += std::pow(h - 10000.0, 2) / 10000.0;
  EXPECT_LT(chi2, 22.5);  // 6 degrees of freedom, p = 0.001
}

TEST(Xoshiro, MatchesTheAuthorsReferenceOutputs) {
  // The first outputs of xoshiro256plusplus.c (Blackman and Vigna) from the state 1, 2, 3, 4.
  Xoshiro256pp g(std::array<std::uint64_t, 4>{1, 2, 3, 4});
  const std::vector<std::uint64_t> expected{41943041ull,
                                            58720359ull,
                                            3588806011781223ull,
                                            3591011842654386ull,
                                            9228616714210784205ull,
                                            9973669472204895162ull,
                                            14011001112246962877ull,
                                            12406186145184390807ull,
                                            15849039046786891736ull,
                                            10450023813501588000ull};
  for (std::uint64_t e : expected) EXPECT_EQ(g(), e);
}
