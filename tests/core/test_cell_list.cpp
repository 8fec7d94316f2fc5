// Cell-list neighbours must equal brute force, including periodic wrap and lattices
// with exactly touching particles (distances equal to the cutoff).
#include <gtest/gtest.h>

#include <set>
#include <utility>

#include "granpipe/cell_list.hpp"
#include "granpipe/random.hpp"
#include "plugin_harness.hpp"

using namespace granpipe;
using Pairs = std::set<std::pair<int, int>>;

namespace {

Pairs brute_force(const Coordinates& x, const Container& c, int dim, double cutoff) {
  Pairs out;
  for (int i = 0; i < x.rows(); ++i)
    for (int j = i + 1; j < x.rows(); ++j) {
      double r2 = 0;
      for (int a = 0; a < dim; ++a) {
        double d = x(j, a) - x(i, a);
        if (c.periodic(a)) d -= c.length(a) * std::round(d / c.length(a));
        r2 += d * d;
      }
      if (r2 <= cutoff * cutoff) out.insert({i, j});
    }
  return out;
}

Pairs cell_pairs(const Coordinates& x, const Container& c, int dim, double cutoff) {
  Pairs out;
  CellList cells(x, c, dim, cutoff);
  cells.for_each_pair([&](int i, int j, const double*, double) {
    EXPECT_TRUE(out.insert({i, j}).second) << "pair visited twice";
  });
  return out;
}

Coordinates random_points(int n, int dim, const Container& c, std::uint64_t seed) {
  RandomStream rng = Seeds(seed).stream("points");
  Coordinates x(n, dim);
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < dim; ++a) x(i, a) = rng.uniform(c.lo[a], c.hi[a]);
  return x;
}

}  // namespace

class CellListRandom : public ::testing::TestWithParam<std::tuple<int, bool, double>> {};

TEST_P(CellListRandom, EqualsBruteForce) {
  const auto [dim, periodic, cutoff] = GetParam();
  const Eigen::Vector3d lo(-1.0, 0.5, 2.0), hi(9.0, 7.5, 8.0);
  const Container c =
      periodic ? Container::periodic_box(dim, lo, hi) : Container::open_top_box(dim, lo, hi);
  const Coordinates x = random_points(dim == 2 ? 400 : 600, dim, c, 7 + dim);
  const Pairs expected = brute_force(x, c, dim, cutoff);
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(cell_pairs(x, c, dim, cutoff), expected);
}

// Cutoffs from small up to half the shortest periodic side, where the grid has fewer
// than three cells per axis and neighbour cells would repeat without deduplication.
INSTANTIATE_TEST_SUITE_P(Boxes, CellListRandom,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Bool(),
                                            ::testing::Values(0.3, 1.1, 2.9)));

TEST(CellList, SquareLatticeExactContactsAcrossPeriodicWrap) {
  // 6x5 square lattice, spacing 1, periodic: every site has exactly 4 neighbours at
  // distance 1, including the ones across the boundary.
  const int nx = 6, ny = 5;
  Coordinates x(nx * ny, 2);
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      x(i * ny + j, 0) = i + 0.5;
      x(i * ny + j, 1) = j + 0.5;
    }
  const Container c =
      Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(nx, ny, 0));
  const Pairs pairs = cell_pairs(x, c, 2, 1.0);
  EXPECT_EQ(pairs.size(), static_cast<std::size_t>(2 * nx * ny));
  EXPECT_EQ(pairs, brute_force(x, c, 2, 1.0));
}

TEST(CellList, FccLatticeTwelveNeighbours) {
  const int n = 3;
  std::vector<Eigen::Vector3d> basis{{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  Coordinates x(4 * n * n * n, 3);
  int k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < n; ++l)
        for (const auto& b : basis) {
          x(k, 0) = i + b[0];
          x(k, 1) = j + b[1];
          x(k, 2) = l + b[2];
          ++k;
        }
  const Container c = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(n, n, n));
  const double nn = std::sqrt(0.5);
  std::vector<int> degree(x.rows(), 0);
  CellList cells(x, c, 3, nn * (1 + 1e-12));
  cells.for_each_pair([&](int i, int j, const double*, double) {
    ++degree[i];
    ++degree[j];
  });
  for (int d : degree) EXPECT_EQ(d, 12);
}

TEST(CellList, ForEachNearMatchesDistanceFilter) {
  const Container c = Container::periodic_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(5, 5, 5));
  const Coordinates x = random_points(300, 3, c, 3);
  CellList cells(x, c, 3, 1.0);
  const double q[3] = {0.1, 4.95, 2.5};  // near two faces: neighbours wrap around
  std::set<int> found, expected;
  cells.for_each_near(q, 0.8, [&](int j, const double*, double) { found.insert(j); });
  for (int j = 0; j < x.rows(); ++j) {
    double r2 = 0;
    for (int a = 0; a < 3; ++a) {
      double d = x(j, a) - q[a];
      d -= 5.0 * std::round(d / 5.0);
      r2 += d * d;
    }
    if (r2 <= 0.64) expected.insert(j);
  }
  EXPECT_EQ(found, expected);
}

TEST(CellList, EmptyAndSingleParticle) {
  const Container c = Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 3, 0));
  Coordinates none(0, 2), one(1, 2);
  one << 1.0, 1.0;
  EXPECT_TRUE(cell_pairs(none, c, 2, 1.0).empty());
  EXPECT_TRUE(cell_pairs(one, c, 2, 1.0).empty());
}

namespace {
std::string error_of(const Coordinates& x, const Container& c, int dim, double cutoff) {
  return test::input_error_of([&] { CellList(x, c, dim, cutoff, "frame 3"); });
}
}  // namespace

// Numbers in %g form, with the digits that tell them apart, and the frame named.
TEST(CellList, PeriodicBoxTooSmallIsAnInputError) {
  const Container c = Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  Coordinates x(2, 2);
  x << 0.1, 0.1, 0.5, 0.5;
  EXPECT_EQ(error_of(x, c, 2, 0.6),
            "frame 3: neighbour search: expected a periodic box of length at least 1.2 (twice the "
            "contact range) "
            "along x, got 1");
  EXPECT_EQ(error_of(x, c, 2, 0.5000000001),
            "frame 3: neighbour search: expected a periodic box of length at least 1.0000000002 "
            "(twice the contact "
            "range) along x, got 1");
}

// An infinite box (phi = 0) or a radius of 1e-200 (squared distances of 0, NaN results)
// is refused, not measured.
TEST(CellList, AbsurdScalesAreInputErrors) {
  const Container huge =
      Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1e308, 1, 0));
  Coordinates x(2, 2);
  x << 0.1, 0.1, 0.5, 0.5;
  EXPECT_EQ(error_of(x, huge, 2, 0.25),
            "frame 3: neighbour search: expected a box at most 1e+09 contact ranges (0.25) long "
            "along x, got a "
            "periodic box of length 1e+308");
  const Container open =
      Container::open_top_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1e12, 0));
  Coordinates far(2, 2);
  far << 0.5, 0.5, 0.5, 1e12;
  EXPECT_EQ(error_of(far, open, 2, 1.0),
            "frame 3: neighbour search: expected a box at most 1e+09 contact ranges (1) long along "
            "y, got particles "
            "spread over 1e+12");
  const Container unit =
      Container::periodic_box(2, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(error_of(x, unit, 2, 2e-200),
            "frame 3: neighbour search: expected a contact range (largest contact distance) from "
            "1e-100 to 1e+100, "
            "got 2e-200");
}

// 10^9 cells per axis would be 10^27 in all: the estimate is made in double and merged
// down before anything is allocated (an integer product overflowed, exit 1).
TEST(CellList, HugeSparseBoxesMergeCellsInsteadOfOverflowing) {
  const Container open =
      Container::open_top_box(3, Eigen::Vector3d::Zero(), Eigen::Vector3d(1e9, 1e9, 1e9));
  Coordinates x(3, 3);
  x << 0, 0, 0, 0.5, 0.5, 0.5, 1e9, 1e9, 1e9;
  EXPECT_EQ(cell_pairs(x, open, 3, 1.0), (Pairs{{0, 1}}));
}
