// Tests of the arches analyzer on hand-built 2D packings whose arches, spans and
// contacts are known exactly (Eqs. (1)-(4) of the 2D tapping paper).
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <utility>

#include "arch_statistics.hpp"
#include "arches_analyzer.hpp"
#include "contact_census.hpp"
#include "granpipe/contacts_by_distance.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/plugin_loader.hpp"
#include "mutual_stability.hpp"
#include "plugin_harness.hpp"
#include "support_count.hpp"
#include "svg_writer.hpp"

namespace ga = granpipe::arches;
using granpipe::Frame;
using granpipe::Wall;
namespace partner = granpipe::partner;

namespace {

constexpr std::int64_t kBase = partner::wall(Wall::YLow);
constexpr std::int64_t kLeftWall = partner::wall(Wall::XLow);
constexpr std::int64_t kRightWall = partner::wall(Wall::XHigh);
constexpr std::int64_t kNone = partner::none;
constexpr double kTolerance = 1e-9;

// Disks of diameter 1 on a triangular lattice: layer k has its centres at this height.
double layer(int k) { return 0.5 + k * std::sqrt(3.0) / 2.0; }

struct Disk {
  double x, y;
  std::int64_t left, right;
};

// The support labels of a test frame, added when missing.
granpipe::ValueTable<std::int64_t>& supports(Frame& f) {
  return f.particles.add<granpipe::ValueTable<std::int64_t>>(ga::supports_property());
}
const granpipe::ValueTable<std::int64_t>& supports(const Frame& f) {
  return f.table<std::int64_t>("supports");
}

Frame make_frame(const std::vector<Disk>& disks, double width) {
  Frame f;
  const auto n = static_cast<Eigen::Index>(disks.size());
  f.resize(n, 2);
  f.container = granpipe::Container::open_top_box(2, {0, 0, 0}, {width, 20, 1});
  f.radius().setConstant(0.5);
  supports(f);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Disk& d = disks[static_cast<std::size_t>(i)];
    f.position()(i, 0) = d.x;
    f.position()(i, 1) = d.y;
    supports(f)(i, 0) = d.left;
    supports(f)(i, 1) = d.right;
  }
  return f;
}

// The left-right mirror image: x -> width - x, left and right supports (and walls) swapped.
Frame mirrored(const Frame& f) {
  Frame m = f;
  const double width = f.container.hi[0] + f.container.lo[0];
  auto swap_wall = [](std::int64_t p) {
    return p == kLeftWall ? kRightWall : p == kRightWall ? kLeftWall : p;
  };
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    m.position()(i, 0) = width - f.position()(i, 0);
    supports(m)(i, 0) = swap_wall(supports(f)(i, 1));
    supports(m)(i, 1) = swap_wall(supports(f)(i, 0));
  }
  return m;
}

// Base b0 (0), b1 (1); arch A (2) - B (3) in layer 1 bridging the gap between them.
Frame two_disk_arch() {
  return make_frame({{0.5, layer(0), kBase, kBase},
                     {2.5, layer(0), kBase, kBase},
                     {1.0, layer(1), 0, 3},
                     {2.0, layer(1), 2, 1}},
                    3.0);
}

// Base b0 (0), b1 (1); arch a1 (2) - a2 (3) - a3 (4) in layer 1 over a two-disk void.
Frame three_disk_chain() {
  return make_frame({{0.5, layer(0), kBase, kBase},
                     {3.5, layer(0), kBase, kBase},
                     {1.0, layer(1), 0, 3},
                     {2.0, layer(1), 2, 4},
                     {3.0, layer(1), 3, 1}},
                    4.0);
}

// Base 0, 1, 2; arches 3-4 and 5-6 in layer 1, the two touching each other (4-5).
Frame two_separate_arches() {
  return make_frame({{0.5, layer(0), kBase, kBase},
                     {2.5, layer(0), kBase, kBase},
                     {4.5, layer(0), kBase, kBase},
                     {1.0, layer(1), 0, 4},
                     {2.0, layer(1), 3, 1},
                     {3.0, layer(1), 1, 6},
                     {4.0, layer(1), 5, 2}},
                    5.0);
}

// A triangular stack deposited one disk at a time: every disk rests on the two below.
Frame sequential_stack() {
  return make_frame({{0.5, layer(0), kBase, kBase},
                     {1.5, layer(0), kBase, kBase},
                     {2.5, layer(0), kBase, kBase},
                     {1.0, layer(1), 0, 1},
                     {2.0, layer(1), 1, 2},
                     {1.5, layer(2), 3, 4}},
                    3.0);
}

// A triangular-lattice packing with a void under a three-disk arch a1-a2-a3 (span 2
// diameters) and a two-disk arch U-V across layers 2 and 3 (span 1/2 diameter): U leans
// on V on its right, as a disk that rolled against V may (its centre lies between its
// two contact points).
enum Lattice { b0, b3, b4, b5, a1, a2, a3, c4, c5, U, W, V, kLatticeDisks };
Frame lattice_with_arches() {
  std::vector<Disk> d(kLatticeDisks);
  d[b0] = {0.5, layer(0), kBase, kBase};
  d[b3] = {3.5, layer(0), kBase, kBase};
  d[b4] = {4.5, layer(0), kBase, kBase};
  d[b5] = {5.5, layer(0), kBase, kBase};
  d[a1] = {1.0, layer(1), b0, a2};
  d[a2] = {2.0, layer(1), a1, a3};
  d[a3] = {3.0, layer(1), a2, b3};
  d[c4] = {4.0, layer(1), b3, b4};
  d[c5] = {5.0, layer(1), b4, b5};
  d[U] = {1.5, layer(2), a1, V};
  d[W] = {2.5, layer(2), a2, a3};
  d[V] = {2.0, layer(3), U, W};
  return make_frame(d, 6.0);
}

std::vector<ga::Arch> arches_of(const Frame& f) {
  ga::check_supports(f, "test");
  return ga::find_arches(f, "test");
}

ga::ContactCensus census_of(const Frame& f) {
  return ga::census_contacts(ga::Supports::of(f),
                             granpipe::find_contacts_by_distance(f, kTolerance));
}

// The same census by brute force over all pairs and walls, with its own contact rule.
ga::ContactCensus brute_force_census(const Frame& f) {
  ga::ContactCensus c;
  const auto& s = ga::Supports::of(f);
  auto names = [&](Eigen::Index i, std::int64_t p) { return s.left(i) == p || s.right(i) == p; };
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    for (Eigen::Index j = i + 1; j < f.size(); ++j) {
      const double dist = std::hypot(f.position()(j, 0) - f.position()(i, 0),
                                     f.position()(j, 1) - f.position()(i, 1));
      if (dist - f.radius()(i) - f.radius()(j) > 1e-9) continue;
      ++c.contacts;
      c.supporting += names(i, j) || names(j, i);
    }
    const double gaps[] = {f.position()(i, 0) - f.radius()(i) - f.container.lo[0],
                           f.container.hi[0] - f.position()(i, 0) - f.radius()(i),
                           f.position()(i, 1) - f.radius()(i) - f.container.lo[1]};
    const std::int64_t walls[] = {kLeftWall, kRightWall, kBase};
    for (int w = 0; w < 3; ++w) {
      if (gaps[w] > 1e-9) continue;
      ++c.contacts;
      c.supporting += names(i, walls[w]);
    }
  }
  return c;
}

// Eq. (4) against the direct count: N + sum_s n(s) - contacts = sum_i (2 - k_i), exactly,
// and the mutual links of the arches are the mutual pairs of the labels.
void expect_eq4_identity(const Frame& f) {
  const auto arches = arches_of(f);
  const ga::ArchStatistics st = ga::arch_statistics(f.size(), arches);
  const ga::SupportCount sc = ga::count_supports(ga::Supports::of(f));
  EXPECT_EQ(f.size() + st.groups() - sc.contacts(), sc.missing_supports());
  Eigen::Index links = 0;
  for (const auto& a : arches) links += static_cast<Eigen::Index>(a.disks.size()) - 1;
  EXPECT_EQ(links, sc.mutual_pairs);
  const double n = static_cast<double>(f.size());
  EXPECT_NEAR(st.z_eq4() - sc.z_direct(), 2.0 * static_cast<double>(sc.missing_supports()) / n,
              1e-12);
  // Eq. (3), written out from p1 and p2, is Eq. (4).
  EXPECT_NEAR(st.z_eq4(),
              4.0 - static_cast<double>(st.p1) / n - 2.0 * static_cast<double>(st.p2) / n, 1e-12);
}

struct Summary {
  std::vector<Eigen::Index> n;
  Eigen::Index p1, p2;
  std::vector<std::pair<std::size_t, double>> size_span;  // sorted
  Eigen::Index contacts, supporting;
};

Summary summarize(const Frame& f) {
  const auto arches = arches_of(f);
  const auto st = ga::arch_statistics(f.size(), arches);
  const auto cc = census_of(f);
  Summary s{st.n, st.p1, st.p2, {}, cc.contacts, cc.supporting};
  for (const auto& a : arches) s.size_span.emplace_back(a.disks.size(), a.span);
  std::sort(s.size_span.begin(), s.size_span.end());
  return s;
}

void expect_mirror_symmetric(const Frame& f) {
  const Summary a = summarize(f), b = summarize(mirrored(f));
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.p1, b.p1);
  EXPECT_EQ(a.p2, b.p2);
  ASSERT_EQ(a.size_span.size(), b.size_span.size());
  for (std::size_t k = 0; k < a.size_span.size(); ++k) {
    EXPECT_EQ(a.size_span[k].first, b.size_span[k].first);
    EXPECT_DOUBLE_EQ(a.size_span[k].second, b.size_span[k].second);
  }
  EXPECT_EQ(a.contacts, b.contacts);
  EXPECT_EQ(a.supporting, b.supporting);
}

}  // namespace

TEST(Arches, TwoDiskArch) {
  const Frame f = two_disk_arch();
  const auto arches = arches_of(f);
  ASSERT_EQ(arches.size(), 1u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{2, 3}));
  EXPECT_EQ(arches[0].span, 1.0);
  const auto st = ga::arch_statistics(f.size(), arches);
  EXPECT_EQ(st.n, (std::vector<Eigen::Index>{0, 2, 1}));
  EXPECT_EQ(st.p1, 2);
  EXPECT_EQ(st.p2, 0);
  EXPECT_EQ(st.arches(), 1);
  EXPECT_DOUBLE_EQ(st.z_eq4(), 3.5);
  const auto sc = ga::count_supports(ga::Supports::of(f));
  EXPECT_EQ(sc.base_disks, 2);
  EXPECT_EQ(sc.mutual_pairs, 1);
  EXPECT_EQ(sc.contacts(), 5);
  EXPECT_DOUBLE_EQ(sc.z_direct(), 2.5);
  // b0-A, A-B, B-b1 and two base contacts support; b0 and b1 touch the side walls.
  const auto cc = census_of(f);
  EXPECT_EQ(cc.contacts, 7);
  EXPECT_EQ(cc.supporting, 5);
  expect_eq4_identity(f);
}

TEST(Arches, ThreeDiskChainIsOneArchFromLeftToRight) {
  const Frame f = three_disk_chain();
  const auto arches = arches_of(f);
  ASSERT_EQ(arches.size(), 1u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{2, 3, 4}));
  EXPECT_EQ(arches[0].span, 2.0);
  const auto st = ga::arch_statistics(f.size(), arches);
  EXPECT_EQ(st.n, (std::vector<Eigen::Index>{0, 2, 0, 1}));
  EXPECT_EQ(st.p1, 2);
  EXPECT_EQ(st.p2, 1);
  EXPECT_DOUBLE_EQ(st.z_eq4(), 3.2);
  expect_eq4_identity(f);
}

TEST(Arches, TwoSeparateArches) {
  const Frame f = two_separate_arches();
  const auto arches = arches_of(f);
  ASSERT_EQ(arches.size(), 2u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{3, 4}));
  EXPECT_EQ(arches[1].disks, (std::vector<Eigen::Index>{5, 6}));
  EXPECT_EQ(arches[0].span, 1.0);
  EXPECT_EQ(arches[1].span, 1.0);
  const auto st = ga::arch_statistics(f.size(), arches);
  EXPECT_EQ(st.n, (std::vector<Eigen::Index>{0, 3, 2}));
  EXPECT_EQ(st.p1, 4);
  EXPECT_EQ(st.p2, 0);
  // The two arches touch (disks 4 and 5) without supporting each other.
  const auto cc = census_of(f);
  EXPECT_EQ(cc.contacts, 12);
  EXPECT_EQ(cc.non_supporting(), 3);
  expect_eq4_identity(f);
}

TEST(Arches, SequentialDepositionHasNoArchesAndEq4GivesFour) {
  const Frame f = sequential_stack();
  const auto arches = arches_of(f);
  EXPECT_TRUE(arches.empty());
  const auto st = ga::arch_statistics(f.size(), arches);
  EXPECT_EQ(st.n, (std::vector<Eigen::Index>{0, 6}));
  EXPECT_EQ(st.p1, 0);
  EXPECT_EQ(st.p2, 0);
  EXPECT_EQ(st.z_eq4(), 4.0);
  // The direct count gives the base disks one support: 4 - 2 N_base / N = 3.
  const auto sc = ga::count_supports(ga::Supports::of(f));
  EXPECT_EQ(sc.mutual_pairs, 0);
  EXPECT_DOUBLE_EQ(sc.z_direct(), 3.0);
  const auto cc = census_of(f);
  EXPECT_EQ(cc.contacts, 14);
  EXPECT_EQ(cc.supporting, 9);
  expect_eq4_identity(f);
}

TEST(Arches, DisksOnTheBaseOnly) {
  const Frame f = make_frame({{0.5, 0.5, kBase, kBase},
                              {2.0, 0.5, kBase, kBase},
                              {3.5, 0.5, kBase, kBase},
                              {5.0, 0.5, kBase, kBase}},
                             6.0);
  const auto st = ga::arch_statistics(f.size(), arches_of(f));
  EXPECT_EQ(st.arches(), 0);
  EXPECT_EQ(st.z_eq4(), 4.0);
  const auto sc = ga::count_supports(ga::Supports::of(f));
  EXPECT_EQ(sc.base_disks, 4);
  EXPECT_EQ(sc.z_direct(), 2.0);
  // Four base contacts and the left wall; the disk at 5.0 is 0.5 from the right wall.
  const auto cc = census_of(f);
  EXPECT_EQ(cc.contacts, 5);
  EXPECT_EQ(cc.supporting, 4);
  expect_eq4_identity(f);
}

TEST(Arches, TriangularLatticeArchesHaveAnalyticSpans) {
  const Frame f = lattice_with_arches();
  const auto arches = arches_of(f);
  ASSERT_EQ(arches.size(), 2u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{a1, a2, a3}));
  EXPECT_EQ(arches[1].disks, (std::vector<Eigen::Index>{U, V}));
  // Two lattice constants along one layer; half a lattice constant from layer 2 to 3.
  EXPECT_EQ(arches[0].span, 2.0);
  EXPECT_EQ(arches[1].span, 0.5);
  const auto st = ga::arch_statistics(f.size(), arches);
  EXPECT_EQ(st.n, (std::vector<Eigen::Index>{0, 7, 1, 1}));
  EXPECT_EQ(st.p1, 4);
  EXPECT_EQ(st.p2, 1);
  EXPECT_DOUBLE_EQ(st.z_eq4(), 3.5);
  const auto sc = ga::count_supports(ga::Supports::of(f));
  EXPECT_EQ(sc.base_disks, 4);
  EXPECT_EQ(sc.contacts(), 17);
  // Supporting: 4 base, 6 layer 1 on the base, a1-a2, a2-a3, U-a1, W-a2, W-a3, V-U, V-W.
  // Not supporting: b0-left wall, b5-right wall, b3-b4, b4-b5, a3-c4, c4-c5, U-a2, U-W.
  const auto cc = census_of(f);
  EXPECT_EQ(cc.contacts, 25);
  EXPECT_EQ(cc.supporting, 17);
  const auto brute = brute_force_census(f);
  EXPECT_EQ(brute.contacts, cc.contacts);
  EXPECT_EQ(brute.supporting, cc.supporting);
  expect_eq4_identity(f);
}

TEST(Arches, MirroredPackingsGiveTheSameResults) {
  expect_mirror_symmetric(two_disk_arch());
  expect_mirror_symmetric(three_disk_chain());
  expect_mirror_symmetric(two_separate_arches());
  expect_mirror_symmetric(sequential_stack());
  expect_mirror_symmetric(lattice_with_arches());
  // The mirror image's arches run from the mirrored right end: a3 first.
  const auto arches = arches_of(mirrored(lattice_with_arches()));
  ASSERT_EQ(arches.size(), 2u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{a3, a2, a1}));
  EXPECT_EQ(arches[1].disks, (std::vector<Eigen::Index>{V, U}));
}

TEST(Arches, PeriodicSpanUsesTheMinimumImage) {
  Frame f = make_frame({{9.5, layer(1), kNone, 1}, {0.5, layer(1), 0, kNone}}, 10.0);
  f.container.boundary[0] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  const auto arches = arches_of(f);
  ASSERT_EQ(arches.size(), 1u);
  EXPECT_EQ(arches[0].disks, (std::vector<Eigen::Index>{0, 1}));
  EXPECT_DOUBLE_EQ(arches[0].span, 1.0);
  EXPECT_EQ(census_of(f).supporting, 1);  // the pair touches through the boundary
  expect_eq4_identity(f);
}

// Any labels, unstable disks included: the identity is algebra, not physics.
TEST(Arches, Eq4IdentityHoldsForRandomLabels) {
  std::mt19937_64 rng(20060107);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 60);
    std::vector<Disk> disks(static_cast<std::size_t>(n));
    // Left supports lie to the left (lower index, smaller x), right ones to the right.
    for (int i = 0; i < n; ++i) {
      auto& d = disks[static_cast<std::size_t>(i)];
      d.x = 0.5 + i;
      d.y = 0.5 + static_cast<double>(rng() % 5);
      const std::int64_t lefts[] = {kNone, kLeftWall, kBase,
                                    i > 0 ? static_cast<std::int64_t>(rng() % i) : kNone};
      const std::int64_t rights[] = {
          kNone, kRightWall, kBase,
          i + 1 < n ? i + 1 + static_cast<std::int64_t>(rng() % (n - i - 1)) : kNone};
      d.left = lefts[rng() % 4];
      d.right = rights[rng() % 4];
    }
    for (int i = 0; i + 1 < n; ++i) {
      if (rng() % 3 == 0) {
        disks[static_cast<std::size_t>(i)].right = i + 1;
        disks[static_cast<std::size_t>(i) + 1].left = i;
      }
    }
    const Frame f = make_frame(disks, n + 1.0);
    SCOPED_TRACE("trial " + std::to_string(trial));
    expect_eq4_identity(f);
    for (const auto& a : arches_of(f)) {
      EXPECT_DOUBLE_EQ(a.span, f.position()(a.disks.back(), 0) - f.position()(a.disks.front(), 0));
    }
  }
}

TEST(Arches, BadSupportLabelsAreInputErrors) {
  Frame f = two_disk_arch();
  supports(f)(2, 0) = 4;  // no disk 4
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  supports(f)(2, 0) = 2;  // itself
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  supports(f)(2, 0) = partner::wall(Wall::YHigh);
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  supports(f)(2, 0) = 3;  // disk 3 as both supports
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  supports(f).conservativeResize(3, 2);
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  f.particles.remove("supports");
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  f = two_disk_arch();
  f.dim = 3;
  EXPECT_THROW(ga::check_supports(f, "test"), granpipe::InputError);
  // A side wall in a box periodic along x made an arch "supported" by a wall not there.
  f = two_disk_arch();
  supports(f)(2, 0) = kLeftWall;
  EXPECT_NO_THROW(ga::check_supports(f, "test"));
  f.container.boundary[0] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  EXPECT_EQ(granpipe::test::input_error_of([&] { ga::check_supports(f, "test"); }),
            "test: supports.left[2]: expected a support the container has, got -2 (wall x_low), "
            "a side it has none on");
}

// A label naming a disk far off passed, a 1 % detached_support_fraction its only trace.
TEST(Arches, SupportsThatDoNotTouchTheirDiskAreInputErrors) {
  Frame f = two_disk_arch();
  ga::check_supports_touch(f, "test");  // touching, and walls a radius off
  supports(f)(2, 0) = 1;                // base disk 1, 1.73 from disk 2's centre
  EXPECT_EQ(granpipe::test::input_error_of([&] { ga::check_supports_touch(f, "test"); }),
            "test: supports.left[2]: expected a support touching disk 2, got disk 1, its surface "
            "0.732051 away (more than the smaller radius, 0.5)");
  f = two_disk_arch();
  supports(f)(3, 1) = kBase;  // disk 3 is in layer 1
  EXPECT_EQ(granpipe::test::input_error_of([&] { ga::check_supports_touch(f, "test"); }),
            "test: supports.right[3]: expected a support touching disk 3, got wall y_low, its "
            "surface 0.866025 away (more than its radius, 0.5)");
}

// Two disks between the walls of a box 2 wide: the right wall labelled as disk 1's left
// support gave 0 arches and a detached fraction of 0.25, and two disks naming each other as
// right supports counted their one contact twice, exit 0.
TEST(Arches, SupportsOnTheWrongSideAreInputErrors) {
  const Frame ok = make_frame({{0.5, 0.5, kLeftWall, 1}, {1.5, 0.5, 0, kRightWall}}, 2.0);
  ga::check_support_sides(ok, "test");
  EXPECT_EQ(granpipe::test::input_error_of([] {
              ga::check_support_sides(
                  make_frame({{0.5, 0.5, kLeftWall, 1}, {1.5, 0.5, kRightWall, 0}}, 2.0), "test");
            }),
            "test: supports.left[1]: expected a support on disk 1's left (the left wall, the "
            "base or a disk), got the wall x_high");
  EXPECT_EQ(granpipe::test::input_error_of([] {
              ga::check_support_sides(
                  make_frame({{0.5, 0.5, kLeftWall, 1}, {1.5, 0.5, kBase, 0}}, 2.0), "test");
            }),
            "test: supports.right[1]: expected a support on disk 1's right (the right wall, the "
            "base or a disk), got disk 0, 1 to its left");
  // Along a periodic x the nearer image decides: disk 0 at x 9.5 is just left of disk 1.
  Frame periodic = make_frame({{9.5, 0.5, kBase, 1}, {0.5, 0.5, 0, kBase}}, 10.0);
  periodic.container.boundary[0] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  ga::check_support_sides(periodic, "test");
}

TEST(Arches, RingOfMutualSupportsIsAnInputError) {
  const Frame f = make_frame({{1.0, 1.0, 2, 1}, {2.0, 1.0, 0, 2}, {3.0, 1.0, 1, 0}}, 4.0);
  ga::check_supports(f, "test");
  EXPECT_THROW(ga::find_arches(f, "test"), granpipe::InputError);
}

namespace {

void count_elements(const boost::property_tree::ptree& node, std::map<std::string, int>& count) {
  for (const auto& [name, child] : node) {
    ++count[name];
    count_elements(child, count);
  }
}

std::map<std::string, int> parse_svg(const std::filesystem::path& path) {
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(path.string(), tree);  // throws unless well-formed
  std::map<std::string, int> count;
  count_elements(tree, count);
  return count;
}

std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   (name + "_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                    "_" + std::to_string(std::random_device{}()));
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace

TEST(ArchesSvg, OneCirclePerDiskAndOneLinePerMutualLink) {
  const auto dir = fresh_directory("arches_svg");
  const Frame f = lattice_with_arches();
  const auto arches = arches_of(f);
  const auto path = dir / "lattice.svg";
  // The picture carries the run's provenance, as every result file does (it had none).
  ga::write_arches_svg(path, f, arches, "lattice <test> & arches",
                       "granpipe 0.1 (abc): run \"a&b\", seed 3");
  const auto count = parse_svg(path);
  EXPECT_EQ(count.at("svg"), 1);
  EXPECT_EQ(count.at("desc"), 1);
  {
    boost::property_tree::ptree svg;
    boost::property_tree::read_xml(path.string(), svg);
    EXPECT_EQ(svg.get<std::string>("svg.desc"), "granpipe 0.1 (abc): run \"a&b\", seed 3");
  }
  EXPECT_EQ(count.at("circle"), kLatticeDisks);
  EXPECT_EQ(count.at("line"), 3);  // a1-a2, a2-a3, U-V
  EXPECT_FALSE(std::filesystem::exists(dir / "lattice.svg.tmp"));

  // Each line joins the centres of two mutually stable disks.
  boost::property_tree::ptree tree;
  boost::property_tree::read_xml(path.string(), tree);
  std::set<std::pair<double, double>> ends;
  std::function<void(const boost::property_tree::ptree&)> collect = [&](const auto& node) {
    for (const auto& [name, child] : node) {
      if (name == "line") {
        ends.insert({child.template get<double>("<xmlattr>.x1"),
                     child.template get<double>("<xmlattr>.y1")});
        ends.insert({child.template get<double>("<xmlattr>.x2"),
                     child.template get<double>("<xmlattr>.y2")});
      }
      collect(child);
    }
  };
  collect(tree);
  std::set<std::pair<double, double>> expected;
  for (Eigen::Index i : {a1, a2, a3, U, V})
    expected.insert({f.position()(i, 0), f.position()(i, 1)});
  ASSERT_EQ(ends.size(), expected.size());
  for (auto e = ends.begin(), x = expected.begin(); e != ends.end(); ++e, ++x) {
    EXPECT_NEAR(e->first, x->first, 1e-6);
    EXPECT_NEAR(e->second, x->second, 1e-6);
  }
  std::filesystem::remove_all(dir);
}

namespace {

// The context of the installed arches plugin, as a pipeline makes it.
std::unique_ptr<granpipe::test::PluginHarness> context(std::int64_t svg_frames, double span_bin,
                                                       const std::filesystem::path& dir = {}) {
  return granpipe::test::make_context("arches",
                                      {{"contact_tolerance", kTolerance},
                                       {"span_bin", span_bin},
                                       {"span_sizes", {2, 3, 4}},
                                       {"svg_frames", svg_frames}},
                                      1, dir);
}

}  // namespace

TEST(ArchesAnalyzer, AveragesOverFramesWithStandardErrors) {
  const auto dir = fresh_directory("arches_analyzer");
  const auto ctx = context(1, 0.25, dir);
  ctx->keep_log();
  ga::ArchesAnalyzer analyzer(*ctx);
  EXPECT_EQ(analyzer.needs().dim, 2);
  ASSERT_EQ(analyzer.needs().columns.size(), 1u);
  EXPECT_TRUE(analyzer.needs().columns[0].matches(ga::supports_property()));

  Frame first = two_disk_arch(), second = three_disk_chain();
  const granpipe::Property tap{"tap", granpipe::Scope::Frame, granpipe::ValueType::Integer, 1, "",
                               ""};
  first.set_observable(tap, std::int64_t{7});
  second.set_observable(tap, std::int64_t{8});
  granpipe::FrameCache cache;
  analyzer.consume(first, cache);
  cache.clear();
  analyzer.consume(second, cache);
  granpipe::Results r;
  analyzer.finish(r);

  EXPECT_EQ(r.scalar("frames").value, 2.0);
  auto expect_mean = [&](const std::string& name, double a, double b) {
    SCOPED_TRACE(name);
    EXPECT_NEAR(r.scalar(name).value, (a + b) / 2, 1e-14);
    EXPECT_NEAR(r.scalar(name).uncertainty, std::abs(a - b) / 2, 1e-14);
  };
  expect_mean("arches_per_particle", 1.0 / 4, 1.0 / 5);
  expect_mean("p1_over_N", 2.0 / 4, 2.0 / 5);
  expect_mean("p2_over_N", 0.0, 1.0 / 5);
  expect_mean("z_support_eq4", 3.5, 3.2);
  expect_mean("z_support_direct", 2.5, 2.0 * 6 / 5);  // 5 and 6 supporting contacts
  expect_mean("z_support_eq4_minus_direct", 2.0 * 2 / 4, 2.0 * 2 / 5);
  expect_mean("base_fraction", 2.0 / 4, 2.0 / 5);
  expect_mean("missing_supports_per_particle", 2.0 / 4, 2.0 / 5);
  expect_mean("non_supporting_contact_fraction", 2.0 / 7, 2.0 / 8);  // the side walls
  expect_mean("detached_support_fraction", 0.0, 0.0);

  // n(s)/N: size 3 first appears in the second frame and counts as 0 in the first.
  const auto& sizes = r.tables().at("arch_size_distribution");
  EXPECT_EQ(sizes.column("s"), (std::vector<double>{1, 2, 3}));
  const auto& ns = sizes.column("n_s_per_N");
  EXPECT_NEAR(ns[0], (2.0 / 4 + 2.0 / 5) / 2, 1e-14);
  EXPECT_NEAR(ns[1], (1.0 / 4 + 0.0) / 2, 1e-14);
  EXPECT_NEAR(ns[2], (0.0 + 1.0 / 5) / 2, 1e-14);
  EXPECT_TRUE(r.plots().at("arch_size_distribution_plot").logy);

  // Spans in diameters: 1 (size 2) and 2 (size 3); bins of 1/4.
  auto density_at = [&](const std::string& name, double x) {
    const auto& h = r.histograms().at(name);
    EXPECT_TRUE(h.density);
    for (std::size_t b = 0; b < h.values.size(); ++b)
      if (h.edges[b] <= x && x < h.edges[b + 1]) return h.values[b];
    return 0.0;
  };
  EXPECT_DOUBLE_EQ(density_at("span_s2", 1.0), 4.0);
  EXPECT_DOUBLE_EQ(density_at("span_s3", 2.0), 4.0);
  EXPECT_DOUBLE_EQ(density_at("span_all", 1.0), 2.0);
  EXPECT_DOUBLE_EQ(density_at("span_all", 2.0), 2.0);
  EXPECT_DOUBLE_EQ(density_at("span_all", 1.5), 0.0);
  for (const auto& [name, h] : r.histograms()) {
    double integral = 0;
    for (std::size_t b = 0; b < h.values.size(); ++b)
      integral += h.values[b] * (h.edges[b + 1] - h.edges[b]);
    if (name == "span_s4") continue;  // no arch of 4 disks: undefined, below
    EXPECT_DOUBLE_EQ(integral, 1.0) << name;
  }
  // No arch of 4 disks: its density is undefined, not 0 (it was one bin of density 0).
  const auto& none = r.histograms().at("span_s4");
  ASSERT_EQ(none.values.size(), 1u);
  EXPECT_TRUE(std::isnan(none.values[0]));
  EXPECT_TRUE(std::isnan(none.errors[0]));
  EXPECT_EQ(ctx->logged_lines(),
            std::vector<std::string>{"warning: arches: no arch of size 4 in any frame: its span "
                                     "distribution span_s4 is undefined (NaN)"});
  // Per frame, Eq. (4) exceeds the direct count by 2 N_base / N.
  const auto& per_frame = r.tables().at("per_frame");
  ASSERT_EQ(per_frame.rows(), 2u);
  EXPECT_EQ(per_frame.column("tap"), (std::vector<double>{7, 8}));
  // These frames have no cycle: undefined, not a cycle -1.
  for (double cycle : per_frame.column("cycle")) EXPECT_TRUE(std::isnan(cycle));
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(per_frame.column("z_support_eq4")[k] - per_frame.column("z_support_direct")[k],
                2 * per_frame.column("base_fraction")[k], 1e-14);
  }

  // Only the first frame is drawn.
  EXPECT_TRUE(std::filesystem::exists(dir / "arches_7.svg"));
  EXPECT_FALSE(std::filesystem::exists(dir / "arches_8.svg"));
  const auto count = parse_svg(dir / "arches_7.svg");
  EXPECT_EQ(count.at("circle"), 4);
  EXPECT_EQ(count.at("line"), 1);
  std::filesystem::remove_all(dir);
}

TEST(ArchesAnalyzer, NoPicturesWithoutAnOutputDirectory) {
  const auto ctx = context(3, 0.05);
  ga::ArchesAnalyzer analyzer(*ctx);
  granpipe::FrameCache cache;
  Frame empty = make_frame({}, 2.0);
  analyzer.consume(empty, cache);  // skipped
  analyzer.consume(lattice_with_arches(), cache);
  granpipe::Results r;
  analyzer.finish(r);
  EXPECT_EQ(r.scalar("frames").value, 1.0);
  EXPECT_NEAR(r.scalar("non_supporting_contact_fraction").value, 8.0 / 25, 1e-15);
  EXPECT_NEAR(r.scalar("z_support_eq4").value, 3.5, 1e-15);
}

TEST(ArchesAnalyzer, DuplicateSpanSizesAreRefused) {
  const auto ctx = granpipe::test::make_context(
      "arches", {{"contact_tolerance", kTolerance}, {"span_sizes", {2, 3, 2}}});
  EXPECT_THROW(ga::ArchesAnalyzer{*ctx}, granpipe::InputError);
}

TEST(ArchesPlugin, LoadsAndDeclaresItsSchema) {
  granpipe::Registry registry;
  granpipe::load_plugins(registry, granpipe::plugin_search_path());
  const auto& info =
      granpipe::require_plugin(registry, "arches", granpipe::PluginKind::Analyzer, "test");
  for (const char* name : {"contact_tolerance", "span_bin", "span_sizes", "svg_frames"}) {
    EXPECT_NE(info.schema.find(name), nullptr) << name;
  }
  const auto ctx = context(0, 0.05);
  const auto analyzer = info.make_analyzer(*ctx);
  ASSERT_EQ(analyzer->needs().columns.size(), 1u);
  EXPECT_EQ(analyzer->needs().columns[0].name, "supports");
  EXPECT_EQ(analyzer->needs().dim, 2);
}

// The analyzer publishes which arch holds each disk: the two arches of two_separate_arches
// (disks 3-4 and 5-6), every other disk in none.
TEST(ArchesAnalyzer, PublishesTheArchOfEachDisk) {
  const auto ctx = context(0, 0.05);
  ga::ArchesAnalyzer analyzer(*ctx);
  ASSERT_EQ(analyzer.publishes().size(), 1u);
  const Frame f = two_separate_arches();
  granpipe::FrameCache cache;
  analyzer.consume(f, cache);
  granpipe::PropertyTable columns(granpipe::Scope::Particle, f.size(), 2);
  columns.add(ga::arch_property());
  analyzer.publish(columns);
  const granpipe::IndexArray& arch = columns.get<granpipe::IndexArray>("arch");
  ASSERT_EQ(arch.size(), f.size());
  EXPECT_EQ(arch[0], -1);
  EXPECT_EQ(arch[1], -1);
  EXPECT_EQ(arch[2], -1);
  EXPECT_EQ(arch[3], arch[4]);
  EXPECT_EQ(arch[5], arch[6]);
  EXPECT_NE(arch[3], arch[5]);
  EXPECT_GE(arch[3], 0);
  EXPECT_GE(arch[5], 0);
}

// A span bin far too small for the spans asked for 10^12 bins and more: std::bad_alloc,
// exit 1. Refused at the first span that would need them, naming the parameter where the
// pipeline has it (the harness's "params"; it said "arches.span_bin" whatever the analyzer's
// name and place).
TEST(ArchesAnalyzer, ASpanBinTooSmallForTheSpansIsRefused) {
  const auto ctx = context(0, 1e-12);
  ga::ArchesAnalyzer analyzer(*ctx);
  granpipe::FrameCache cache;
  try {
    analyzer.consume(lattice_with_arches(), cache);
    FAIL() << "expected an InputError";
  } catch (const granpipe::InputError& e) {
    EXPECT_EQ(
        std::string(e.what()).rfind(
            "params.span_bin: expected at most 10000000 bins of the span distributions, got ", 0),
        0u)
        << e.what();
  }
}

// Two disks floating apart, no support and no contact: the contact fractions and the span
// distribution are NaN (0/0), and were so without a word.
TEST(ArchesAnalyzer, FractionsOfNothingAreSaidUndefined) {
  const auto ctx = context(0, 0.25);
  ctx->keep_log();
  ga::ArchesAnalyzer analyzer(*ctx);
  granpipe::FrameCache cache;
  analyzer.consume(make_frame({{1.0, 3.0, kNone, kNone}, {5.0, 3.0, kNone, kNone}}, 10.0), cache);
  granpipe::Results r;
  analyzer.finish(r);
  EXPECT_TRUE(std::isnan(r.scalar("non_supporting_contact_fraction").value));
  EXPECT_TRUE(std::isnan(r.scalar("detached_support_fraction").value));
  const std::vector<std::string> log = ctx->logged_lines();
  const auto said = [&](const std::string& line) {
    return std::find(log.begin(), log.end(), line) != log.end();
  };
  EXPECT_TRUE(
      said("warning: arches: frame 0: no disk touches another or a wall: its "
           "non_supporting_contact_fraction is undefined (NaN in per_frame); said for the "
           "first such frame only"));
  EXPECT_TRUE(
      said("warning: arches: no frame had a contact: non_supporting_contact_fraction is "
           "undefined (NaN)"));
  EXPECT_TRUE(
      said("warning: arches: no frame had a supporting contact: "
           "detached_support_fraction is undefined (NaN)"));
  EXPECT_TRUE(
      said("warning: arches: no arch in any frame: the span distribution span_all is "
           "undefined (NaN)"));
}
