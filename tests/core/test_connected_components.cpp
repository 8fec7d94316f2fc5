// Connected components: labels by size, ties by the smallest particle, whatever the order
// of the edges; particles without edges in none.
#include <gtest/gtest.h>

#include <vector>

#include "granpipe/connected_components.hpp"
#include "granpipe/errors.hpp"

using namespace granpipe;

namespace {

std::vector<std::int64_t> labels(const ConnectedComponents& c) {
  return {c.label.begin(), c.label.end()};
}

}  // namespace

TEST(ConnectedComponents, LabelsBySizeDescending) {
  // {0, 5} two particles, {1, 2, 3} three with a loop (3 edges), 4 alone.
  const std::vector<ParticlePair> edges = {{0, 5}, {1, 2}, {2, 3}, {3, 1}};
  const ConnectedComponents c = connected_components(6, edges);
  EXPECT_EQ(labels(c), (std::vector<std::int64_t>{1, 0, 0, 0, -1, 1}));
  ASSERT_EQ(c.size.size(), 2u);
  EXPECT_EQ(c.size[0].particles, 3);
  EXPECT_EQ(c.size[0].edges, 3);
  EXPECT_EQ(c.size[1].particles, 2);
  EXPECT_EQ(c.size[1].edges, 1);
}

TEST(ConnectedComponents, TiesGoToTheSmallestParticleWhateverTheEdgeOrder) {
  // {1, 4} and {2, 3}: equal sizes, {1, 4} holds the smaller particle.
  for (const auto& edges :
       {std::vector<ParticlePair>{{1, 4}, {3, 2}}, std::vector<ParticlePair>{{2, 3}, {4, 1}}}) {
    const ConnectedComponents c = connected_components(5, edges);
    EXPECT_EQ(labels(c), (std::vector<std::int64_t>{-1, 0, 1, 1, 0}));
  }
}

TEST(ConnectedComponents, AnEdgeGivenTwiceCountsTwice) {
  const std::vector<ParticlePair> edges = {{0, 1}, {1, 0}};
  const ConnectedComponents c = connected_components(2, edges);
  ASSERT_EQ(c.size.size(), 1u);
  EXPECT_EQ(c.size[0].particles, 2);
  EXPECT_EQ(c.size[0].edges, 2);
}

TEST(ConnectedComponents, IsolatedParticlesAreInNone) {
  const ConnectedComponents c = connected_components(3, {});
  EXPECT_EQ(labels(c), (std::vector<std::int64_t>{-1, -1, -1}));
  EXPECT_TRUE(c.size.empty());
}

TEST(ConnectedComponents, EmptyInput) {
  const ConnectedComponents c = connected_components(0, {});
  EXPECT_EQ(c.label.size(), 0);
  EXPECT_TRUE(c.size.empty());
}

TEST(ConnectedComponents, RefusesAnEdgeOutsideTheParticlesOrToItself) {
  const std::vector<ParticlePair> outside = {{0, 3}};
  EXPECT_THROW(
      {
        try {
          connected_components(3, outside);
        } catch (const InternalError& e) {
          EXPECT_STREQ(e.what(),
                       "connected_components: expected an edge between two different "
                       "particles below 3, got 0 and 3");
          throw;
        }
      },
      InternalError);
  const std::vector<ParticlePair> loop = {{1, 1}};
  EXPECT_THROW(connected_components(3, loop), InternalError);
}
