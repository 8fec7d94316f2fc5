// The huge-page allocator: memory that behaves as any vector's, on 2 MB boundaries when
// large (whether the kernel then backs it with huge pages is its choice, not tested).
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "granpipe/huge_pages.hpp"

using granpipe::HugePageVector;

namespace {

bool on_huge_page_boundary(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % granpipe::huge_pages::kPage == 0;
}

}  // namespace

TEST(HugePages, ALargeVectorStartsOnATwoMegabyteBoundaryAndHoldsItsValues) {
  HugePageVector<double> v(700'001);  // 5.6 MB: not a whole number of pages
  EXPECT_TRUE(on_huge_page_boundary(v.data()));
  std::iota(v.begin(), v.end(), 0.0);
  EXPECT_EQ(v.front(), 0.0);
  EXPECT_EQ(v.back(), 700'000.0);
  EXPECT_EQ(std::accumulate(v.begin(), v.end(), 0.0), 700'000.0 * 700'001.0 / 2.0);
}

TEST(HugePages, GrowingKeepsTheValuesAndSmallVectorsAreOrdinary) {
  HugePageVector<std::int32_t> v;
  for (std::int32_t i = 0; i < 2'000'000; ++i) v.push_back(i);  // through many reallocations
  EXPECT_TRUE(on_huge_page_boundary(v.data()));
  for (std::int32_t i = 0; i < 2'000'000; i += 99'991) EXPECT_EQ(v[static_cast<std::size_t>(i)], i);
  v.resize(10);
  v.shrink_to_fit();
  EXPECT_EQ(v.size(), 10u);
  EXPECT_EQ(v[9], 9);
  HugePageVector<double> small(100, 1.5);
  EXPECT_EQ(std::accumulate(small.begin(), small.end(), 0.0), 150.0);
}
