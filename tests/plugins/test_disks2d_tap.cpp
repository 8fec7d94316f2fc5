// Tests of the disks2d_tap source: exact contacts of single moves, the support rules of
// the Manna-Khakhar deposition, whole depositions checked against an independent test
// of stability, the tap, the schedules and reproducibility.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <numeric>
#include <set>

#include "deposit.hpp"
#include "disk_packing.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/frame_store.hpp"
#include "granpipe/plugin.hpp"
#include "placement.hpp"
#include "plugin_harness.hpp"
#include "shake.hpp"
#include "tap_schedule.hpp"
#include "tap_source.hpp"
#include "visit_order.hpp"

namespace dt = granpipe::disks2d_tap;
namespace fs = std::filesystem;
using granpipe::Frame;
using granpipe::InputError;
using granpipe::RandomStream;
using granpipe::Seeds;
using granpipe::Wall;
namespace partner = granpipe::partner;

namespace {

const double kR = 0.1 + 1.0 / std::numbers::sqrt2;  // the paper's radius

double distance(const dt::DiskPacking& p, std::size_t i, std::size_t j) {
  return std::hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]);
}

// Moves disk i until a move of the given kind happens; fails after `limit` moves.
void move_until(dt::Deposit& d, std::int32_t i, dt::Move wanted, int limit = 100000) {
  for (int n = 0; n < limit; ++n) {
    if (d.move(i) == wanted) return;
  }
  FAIL() << "disk " << i << " never made move " << static_cast<int>(wanted);
}

// Independent check of a finished deposition, from the frame's left/right labels:
// no overlaps, every disk on the base or touching two supports with its centre's x
// between their contact points.
void expect_deposited(const dt::DiskPacking& p) {
  const double tol = 1e-9;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      ASSERT_GE(distance(p, i, j), (p.r[i] + p.r[j]) * (1.0 - tol)) << i << " overlaps " << j;
    }
    ASSERT_GE(p.x[i] - p.r[i], -tol * p.r[i]);
    ASSERT_LE(p.x[i] + p.r[i], p.width + tol * p.r[i]);
    ASSERT_GE(p.y[i] - p.r[i], -tol * p.r[i]);
  }
  Frame f;
  p.to_frame(f);
  ASSERT_TRUE(f.has("supports"));
  for (Eigen::Index k = 0; k < f.size(); ++k) {
    const auto i = static_cast<std::size_t>(k);
    const std::int64_t left = f.table<std::int64_t>("supports")(k, 0),
                       right = f.table<std::int64_t>("supports")(k, 1);
    const std::int64_t base = partner::wall(Wall::YLow);
    if (left == base || right == base) {
      EXPECT_EQ(left, base);
      EXPECT_EQ(right, base);
      EXPECT_NEAR(p.y[i], p.r[i], 1e-12 * p.r[i]) << "disk " << i << " labelled on the base";
      continue;
    }
    ASSERT_NE(left, partner::none) << "disk " << i << " has no left support";
    ASSERT_NE(right, partner::none) << "disk " << i << " has no right support";
    ASSERT_NE(left, right);
    // Touching, and where: the contact point's x.
    auto contact_x = [&](std::int64_t s) {
      if (s == partner::wall(Wall::XLow)) {
        EXPECT_NEAR(p.x[i], p.r[i], tol * p.r[i]);
        return 0.0;
      }
      if (s == partner::wall(Wall::XHigh)) {
        EXPECT_NEAR(p.x[i], p.width - p.r[i], tol * p.r[i]);
        return p.width;
      }
      EXPECT_TRUE(partner::is_particle(s));
      const auto j = static_cast<std::size_t>(s);
      EXPECT_NEAR(distance(p, i, j), p.r[i] + p.r[j], tol * p.r[i]) << i << " and " << j;
      return p.x[i] + (p.x[j] - p.x[i]) * p.r[i] / (p.r[i] + p.r[j]);
    };
    EXPECT_LE(contact_x(left), p.x[i]) << "disk " << i;
    EXPECT_GE(contact_x(right), p.x[i]) << "disk " << i;
  }
}

// Pairs of disks that are each other's supports.
int mutual_pairs(const dt::DiskPacking& p) {
  Frame f;
  p.to_frame(f);
  int pairs = 0;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    const std::int64_t r = f.table<std::int64_t>("supports")(i, 1);
    if (partner::is_particle(r) && f.table<std::int64_t>("supports")(r, 0) == i) ++pairs;
  }
  return pairs;
}

dt::DiskPacking random_bed(std::size_t n, double width, double spread, std::uint64_t seed) {
  RandomStream rng(seed);
  std::vector<double> radii(n, kR);
  for (double& r : radii) r *= 1.0 + spread * (2.0 * rng.uniform() - 1.0);
  const double height = static_cast<double>(n) * std::numbers::pi * kR * kR / (width * 0.3);
  return dt::place_at_random(width, height, radii, rng, "test");
}

}  // namespace

TEST(Disks2dTapFall, StopsExactlyOnTheBase) {
  dt::DiskPacking p;
  p.width = 10.0;
  p.add(5.0, 7.3, kR);
  dt::Deposit d(p, {});
  RandomStream rng(1);
  d.run(rng);
  EXPECT_EQ(p.y[0], kR);  // placed at contact exactly
  EXPECT_EQ(p.x[0], 5.0);
  EXPECT_TRUE(p.on_base(0));
  // delta = 0.01: 7.3 - r needs ceil((7.3 - r) / 0.01) falls, the last one shortened.
  EXPECT_EQ(d.stats().falls, static_cast<std::uint64_t>(std::ceil((7.3 - kR) / 0.01)));
  EXPECT_EQ(d.stats().rolls, 0u);
}

TEST(Disks2dTapFall, StopsExactlyOnARestingDisk) {
  for (const double offset : {0.0, 0.3, -1.1, 1.6}) {  // 1.6: a grazing contact (2r = 1.614)
    dt::DiskPacking p;
    p.width = 10.0;
    p.add(5.0, kR, kR);            // on the base
    p.add(5.0 + offset, 9.0, kR);  // falls onto it
    dt::Deposit d(p, {});
    move_until(d, 1, dt::Move::LandOnDisk);
    EXPECT_NEAR(distance(p, 0, 1), 2.0 * kR, 1e-12 * 2.0 * kR) << "offset " << offset;
    EXPECT_EQ(p.x[1], 5.0 + offset);
    EXPECT_EQ(p.first[1], 0);
    EXPECT_EQ(p.second[1], dt::kNone);
    ASSERT_EQ(d.supported_by(0).size(), 1u);
    EXPECT_EQ(d.supported_by(0)[0], 1);
  }
}

TEST(Disks2dTapRoll, MovesTheCentreAnArcDeltaAroundItsSupport) {
  for (const auto measure : {dt::RollMeasure::CentrePath, dt::RollMeasure::SupportSurface}) {
    dt::DiskPacking p;
    p.width = 10.0;
    p.add(5.0, kR, kR);
    const double angle0 = 1.2;  // from the horizontal
    p.add(5.0 + 2 * kR * std::cos(angle0), kR + 2 * kR * std::sin(angle0), kR);
    p.first[1] = 0;
    dt::DepositOptions o;
    o.delta = 0.02;
    o.measure = measure;
    dt::Deposit d(p, o);
    ASSERT_EQ(d.move(1), dt::Move::Roll);
    const double angle1 = std::atan2(p.y[1] - p.y[0], p.x[1] - p.x[0]);
    const double divisor = measure == dt::RollMeasure::CentrePath ? 2 * kR : kR;
    EXPECT_NEAR(angle0 - angle1, o.delta / divisor, 1e-12);  // downhill: to the right
    EXPECT_NEAR(distance(p, 0, 1), 2 * kR, 1e-12 * kR);
  }
}

TEST(Disks2dTapRoll, LosesItsSupportAtTheSupportsHeightAndFalls) {
  dt::DiskPacking p;
  p.width = 10.0;
  p.add(5.0, kR, kR);
  p.add(5.0 - 0.4, 9.0, kR);  // lands left of the top: rolls to the left
  dt::Deposit d(p, {});
  move_until(d, 1, dt::Move::LandOnDisk);
  move_until(d, 1, dt::Move::RollOff);
  EXPECT_EQ(p.y[1], p.y[0]);  // cut exactly at the support's height
  EXPECT_NEAR(p.x[1], 5.0 - 2 * kR, 1e-12 * kR);
  EXPECT_EQ(p.first[1], dt::kNone);
  EXPECT_TRUE(d.supported_by(0).empty());
  // Lost it: the next move is a free fall beside it, down to the base.
  EXPECT_EQ(d.move(1), dt::Move::LandOnBase);
  EXPECT_EQ(p.y[1], kR);
  EXPECT_TRUE(d.done());
}

TEST(Disks2dTapRoll, ComesToRestAgainstAWall) {
  // A channel 3r wide: a disk lands on one resting against the left wall and rolls into
  // the right wall, where the wall and the disk below hold it.
  dt::DiskPacking p;
  p.width = 3.0 * kR;
  p.add(kR, kR, kR);
  p.add(1.6 * kR, 12.0, kR);
  dt::Deposit d(p, {});
  RandomStream rng(2);
  d.run(rng);
  EXPECT_NEAR(p.x[1], 2.0 * kR, 1e-12 * kR);  // touches the right wall
  EXPECT_NEAR(p.y[1], kR + std::sqrt(3.0) * kR, 1e-12 * kR);
  EXPECT_NEAR(distance(p, 0, 1), 2 * kR, 1e-12 * kR);
  Frame f;
  p.to_frame(f);
  EXPECT_EQ(f.table<std::int64_t>("supports")(1, 0), 0);
  EXPECT_EQ(f.table<std::int64_t>("supports")(1, 1), partner::wall(Wall::XHigh));
  EXPECT_EQ(f.table<std::int64_t>("supports")(0, 0), partner::wall(Wall::YLow));
  EXPECT_EQ(f.table<std::int64_t>("supports")(0, 1), partner::wall(Wall::YLow));
}

TEST(Disks2dTapRoll, ADiskExactlyOnTopRollsAwayFromTheWall) {
  // Both disks touch the left wall, so the upper lands exactly on top: downhill is
  // undefined and the disk must not settle against the wall on a single support.
  dt::DiskPacking p;
  p.width = 10.0;
  p.add(kR, kR, kR);
  p.add(kR, 8.0, kR);
  dt::Deposit d(p, {});
  move_until(d, 1, dt::Move::LandOnDisk);
  EXPECT_EQ(p.x[1], kR);
  EXPECT_EQ(d.move(1), dt::Move::Roll);
  EXPECT_GT(p.x[1], kR);
  RandomStream rng(3);
  d.run(rng);
  EXPECT_NEAR(p.x[1], 3.0 * kR, 1e-12 * kR);  // rolled off to the right, onto the base
  EXPECT_EQ(p.y[1], kR);
}

TEST(Disks2dTapSupports, DisksRestingOnAMovingDiskLoseIt) {
  // S on the base; M rolls on S, 20 degrees up; T rests stably on M (30 degrees up it,
  // out of M's way) and on Q, on the base.
  dt::DiskPacking p;
  p.width = 20.0;
  const double a20 = std::numbers::pi / 9, a30 = std::numbers::pi / 6;
  p.add(5.0, kR, kR);                                                    // 0: S
  p.add(5.0 + 2 * kR * std::cos(a20), kR + 2 * kR * std::sin(a20), kR);  // 1: M
  const double tx = p.x[1] + 2 * kR * std::cos(a30), ty = p.y[1] + 2 * kR * std::sin(a30);
  p.add(tx + std::sqrt(4 * kR * kR - (ty - kR) * (ty - kR)), kR, kR);  // 2: Q
  p.add(tx, ty, kR);                                                   // 3: T
  p.first[1] = 0;
  p.first[3] = 1;
  p.second[3] = 2;
  ASSERT_NEAR(distance(p, 1, 3), 2 * kR, 1e-12);
  ASSERT_NEAR(distance(p, 2, 3), 2 * kR, 1e-12);
  ASSERT_TRUE(p.x[3] > p.x[1] && p.x[3] < p.x[2]) << "T must rest stably";
  dt::Deposit dep(p, {});
  ASSERT_EQ(dep.unstable().size(), 1u);  // only M
  ASSERT_EQ(dep.supported_by(1).size(), 1u);

  ASSERT_EQ(dep.move(1), dt::Move::Roll);
  EXPECT_EQ(p.first[3], 2);  // Q became T's first support
  EXPECT_EQ(p.second[3], dt::kNone);
  EXPECT_TRUE(dep.supported_by(1).empty());
  ASSERT_EQ(dep.supported_by(2).size(), 1u);
  EXPECT_EQ(dep.supported_by(2)[0], 3);
  EXPECT_EQ(dep.unstable().size(), 2u);  // M and T
  RandomStream rng(4);
  dep.run(rng);
  expect_deposited(p);
}

TEST(Disks2dTapSupports, ALoneWallHoldsNothingUp) {
  // A disk held by a disk and the right wall falls when that disk moves away.
  dt::DiskPacking p;
  p.width = 3.0 * kR;
  p.add(kR, kR + 2.0, kR);                              // 0: lifted off the base, about to fall
  p.add(2.0 * kR, kR + 2.0 + std::sqrt(3.0) * kR, kR);  // 1: against the right wall on 0
  p.first[1] = 0;
  p.second[1] = dt::kRightWall;
  dt::Deposit d(p, {});
  ASSERT_EQ(d.move(0), dt::Move::Fall);
  EXPECT_EQ(p.first[1], dt::kNone);
  EXPECT_EQ(p.second[1], dt::kNone);
}

TEST(Disks2dTapDeposition, SequentialDepositionMakesNoMutualContacts) {
  dt::DiskPacking p;
  p.width = 12.0;
  RandomStream rng(5);
  dt::Deposit d(p, {});
  for (int k = 0; k < 150; ++k) {
    p.add(rng.uniform(kR, p.width - kR), p.top() + kR + rng.uniform(0.0, 1.0), kR);
    d.reset();
    d.run(rng);
    ASSERT_TRUE(d.done());
  }
  expect_deposited(p);
  EXPECT_EQ(mutual_pairs(p), 0);
  // With no arches, Eq. (4) gives <z>_support = 2 (1 + n(1)/N) with n(1) = N: 4 exactly;
  // and the direct count gives two distinct supports per disk off the base.
  Frame f;
  p.to_frame(f);
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    if (f.table<std::int64_t>("supports")(i, 0) != partner::wall(Wall::YLow)) {
      EXPECT_NE(f.table<std::int64_t>("supports")(i, 0), f.table<std::int64_t>("supports")(i, 1));
    }
  }
}

TEST(Disks2dTapDeposition, EndsWithEveryDiskStableAndNoOverlap) {
  for (const auto order : {dt::MoveOrder::Sweeps, dt::MoveOrder::Random}) {
    for (const auto update : {dt::SupportUpdate::Drop, dt::SupportUpdate::KeepTouching}) {
      for (const double spread : {0.0, 0.3}) {
        dt::DiskPacking p = random_bed(300, 15.0, spread, 6);
        dt::DepositOptions o;
        o.delta = 0.05;
        o.order = order;
        o.update = update;
        dt::Deposit d(p, o);
        RandomStream rng(7);
        d.run(rng);
        ASSERT_TRUE(d.done());
        SCOPED_TRACE(testing::Message() << "order " << int(order) << " update " << int(update)
                                        << " spread " << spread);
        expect_deposited(p);
        EXPECT_NO_THROW(p.check("test", 1e-9));
        EXPECT_GT(mutual_pairs(p), 0);  // simultaneous deposition builds arches
      }
    }
  }
}

// Far from the origin one ulp of x outgrows the engine's contact tolerances (7e-12 at
// x = 32768). Rolls to a contact a few ulps ahead then went nowhere forever (a wide bed
// never finished), and grazing contacts were missed (a bed 10^5 wide overlapped).
TEST(Disks2dTapDeposition, FarFromTheOriginEndsStableWithoutOverlap) {
  for (const double offset : {4e4, 1.5e5}) {
    dt::DiskPacking p = random_bed(1000, 30.0, 0.0, 11);
    for (double& x : p.x) x += offset;
    p.width += offset;
    dt::Deposit d(p, {.delta = 0.01});
    RandomStream rng(12);
    // Moves one random unstable disk at a time, within a budget: a disk rolling by nothing
    // forever fails the test instead of hanging it.
    constexpr std::uint64_t kBudget = 20'000'000;
    while (!d.done() && d.stats().moves() < kBudget)
      d.move(d.unstable()[rng.below(d.unstable().size())]);
    SCOPED_TRACE(testing::Message() << "offset " << offset << ", moves " << d.stats().moves());
    ASSERT_TRUE(d.done());
    EXPECT_NO_THROW(p.check("test", 1e-9));
  }
}

TEST(Disks2dTapShake, DilationScalesHeightsAndMonteCarloNeverOverlaps) {
  dt::DiskPacking p = random_bed(300, 15.0, 0.2, 8);
  dt::Deposit d(p, {.delta = 0.05});
  RandomStream rng(9);
  d.run(rng);
  const std::vector<double> y0 = p.y;

  dt::DiskPacking dilated = p;
  dt::Shaker(0, dt::Dilation::CentreHeight).tap(dilated, 1.3, rng);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(dilated.y[i], 1.3 * y0[i]);
    EXPECT_EQ(dilated.first[i], dt::kNone);
  }
  dt::DiskPacking above = p;
  dt::Shaker(0, dt::Dilation::HeightAboveContact).tap(above, 1.3, rng);
  const double r_min = p.min_radius();
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(above.y[i] - r_min, 1.3 * (y0[i] - r_min), 1e-12 * y0[i]);
  }

  for (const double A : {1.05, 1.5, 2.0}) {
    dt::DiskPacking q = p;
    dt::Shaker shaker(20, dt::Dilation::CentreHeight);
    shaker.tap(q, A, rng);
    EXPECT_GT(shaker.stats().accepted, 0u);
    EXPECT_LT(shaker.stats().accepted, shaker.stats().trials);
    double moved = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      moved = std::max(moved, std::abs(q.x[i] - p.x[i]));
      ASSERT_GE(q.x[i] - q.r[i], 0.0);
      ASSERT_LE(q.x[i] + q.r[i], q.width);
      ASSERT_GE(q.y[i] - q.r[i], 0.0);
      for (std::size_t j = i + 1; j < q.size(); ++j) {
        // Pairs touching before the tap may keep their distance to rounding.
        ASSERT_GE(distance(q, i, j), (q.r[i] + q.r[j]) * (1.0 - 1e-12));
      }
    }
    EXPECT_GT(moved, 0.0);
    EXPECT_LE(moved, 20 * (A - 1.0));
  }
}

TEST(Disks2dTapShake, AmplitudeOneIsNoTap) {
  dt::DiskPacking p = random_bed(100, 10.0, 0.0, 10);
  dt::Deposit d(p, {.delta = 0.05});
  RandomStream rng(11);
  d.run(rng);
  dt::DiskPacking q = p;
  dt::Shaker(20, dt::Dilation::CentreHeight).tap(q, 1.0, rng);
  EXPECT_EQ(q.x, p.x);
  EXPECT_EQ(q.y, p.y);
  EXPECT_EQ(q.first, p.first);
  EXPECT_EQ(q.second, p.second);
}

TEST(Disks2dTapVisitOrder, IndexOrderIsTheSameInEveryLoopAndDrawsNothing) {
  dt::VisitOrder order(dt::McOrder::Index);
  order.reset(40);
  std::vector<std::int32_t> by_index(40);
  std::iota(by_index.begin(), by_index.end(), 0);
  RandomStream rng(1), untouched(1);
  for (int loop = 0; loop < 3; ++loop) EXPECT_EQ(order.next(rng), by_index);
  EXPECT_EQ(rng.bits(), untouched.bits());
}

TEST(Disks2dTapVisitOrder, ShuffledVisitsEveryDiskOncePerLoopInAFreshOrder) {
  const std::size_t n = 50;
  std::vector<std::int32_t> by_index(n);
  std::iota(by_index.begin(), by_index.end(), 0);
  auto loops = [&](std::uint64_t seed) {
    dt::VisitOrder order(dt::McOrder::Shuffled);
    order.reset(n);
    RandomStream rng(seed);
    const std::int32_t* buffer = order.next(rng).data();
    std::vector<std::vector<std::int32_t>> seen;
    for (int loop = 0; loop < 20; ++loop) {
      const std::vector<std::int32_t>& disks = order.next(rng);
      EXPECT_EQ(disks.data(), buffer) << "loop " << loop << " reallocated the order";
      seen.push_back(disks);
    }
    order.reset(n);  // the next tap reuses the buffer too
    EXPECT_EQ(order.next(rng).data(), buffer);
    return seen;
  };
  const auto a = loops(5), b = loops(5), c = loops(6);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  for (std::size_t loop = 0; loop < a.size(); ++loop) {
    std::vector<std::int32_t> sorted = a[loop];
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, by_index) << "loop " << loop << " is not a permutation";
    EXPECT_NE(a[loop], by_index);
    if (loop > 0) {
      EXPECT_NE(a[loop], a[loop - 1]);
    }
  }
}

// Fresh means uniform: each of the 3! orders of three disks comes up about equally often,
// not a fixed cycle of a few (expected 1000 each, standard deviation 29).
TEST(Disks2dTapVisitOrder, ShuffledOrdersAreUniform) {
  dt::VisitOrder order(dt::McOrder::Shuffled);
  order.reset(3);
  RandomStream rng(7);
  std::map<std::vector<std::int32_t>, int> count;
  for (int loop = 0; loop < 6000; ++loop) ++count[order.next(rng)];
  ASSERT_EQ(count.size(), 6u);
  for (const auto& [disks, n] : count) {
    EXPECT_GT(n, 850);
    EXPECT_LT(n, 1150);
  }
}

TEST(Disks2dTapShake, ShuffledOrderIsReproducibleAndDiffersFromIndexOrder) {
  dt::DiskPacking p = random_bed(200, 12.0, 0.0, 12);
  dt::Deposit d(p, {.delta = 0.05});
  RandomStream rng(13);
  d.run(rng);
  auto tapped = [&](dt::McOrder order, std::uint64_t seed) {
    dt::DiskPacking q = p;
    RandomStream tap_rng(seed);
    dt::Shaker(20, dt::Dilation::CentreHeight, order).tap(q, 1.2, tap_rng);
    return q;
  };
  const dt::DiskPacking a = tapped(dt::McOrder::Shuffled, 3), b = tapped(dt::McOrder::Shuffled, 3);
  const dt::DiskPacking by_index = tapped(dt::McOrder::Index, 3);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_NE(a.x, by_index.x);
  EXPECT_NE(a.y, by_index.y);
}

TEST(Disks2dTapShake, TapsInShuffledOrderLeaveNoOverlap) {
  dt::DiskPacking p = random_bed(300, 15.0, 0.2, 14);
  dt::Deposit d(p, {.delta = 0.05});
  RandomStream rng(15);
  d.run(rng);
  dt::Shaker shaker(20, dt::Dilation::CentreHeight, dt::McOrder::Shuffled);
  for (const double A : {1.05, 1.2, 1.5, 1.1}) {
    SCOPED_TRACE(testing::Message() << "A = " << A);
    shaker.tap(p, A, rng);
    for (std::size_t i = 0; i < p.size(); ++i) {
      ASSERT_GE(p.x[i] - p.r[i], 0.0);
      ASSERT_LE(p.x[i] + p.r[i], p.width);
      ASSERT_GE(p.y[i] - p.r[i], 0.0);
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        // Pairs touching before the tap may keep their distance to rounding.
        ASSERT_GE(distance(p, i, j), (p.r[i] + p.r[j]) * (1.0 - 1e-12)) << i << " and " << j;
      }
    }
    d.reset();
    d.run(rng);
    ASSERT_TRUE(d.done());
    expect_deposited(p);
  }
  EXPECT_GT(shaker.stats().accepted, 0u);
  EXPECT_LT(shaker.stats().accepted, shaker.stats().trials);
}

TEST(Disks2dTapPacking, CheckRejectsBadConfigurations) {
  dt::DiskPacking p;
  p.width = 10.0;
  p.add(2.0, 2.0, kR);
  p.add(2.0 + 1.5 * kR, 2.0, kR);  // overlaps the first
  EXPECT_THROW(p.check("scene", 1e-9), InputError);
  p.x[1] = 2.0 + 2.0 * kR;
  EXPECT_NO_THROW(p.check("scene", 1e-9));
  p.y[1] = std::nan("");
  EXPECT_THROW(p.check("scene", 1e-9), InputError);
  p.y[1] = 2.0;
  p.x[1] = 10.0 - 0.5 * kR;  // through the right wall
  EXPECT_THROW(p.check("scene", 1e-9), InputError);
}

TEST(Disks2dTapPacking, ADepositedBedReadBackFromItsFrameStaysPut) {
  dt::DiskPacking bed = random_bed(300, 15.0, 0.2, 21);
  RandomStream deposition(22);
  dt::Deposit(bed, {.delta = 0.05}).run(deposition);
  Frame saved;
  bed.to_frame(saved);

  dt::DiskPacking again = dt::DiskPacking::from_frame(saved, "saved");
  EXPECT_EQ(again.width, 15.0);
  EXPECT_EQ(again.x, bed.x);
  EXPECT_EQ(again.y, bed.y);
  EXPECT_EQ(again.r, bed.r);
  EXPECT_EQ(again.first, std::vector<dt::PartnerCode>(300, dt::kNone));
  // Every disk already rests on its supports: depositing again finds them without moving.
  dt::Deposit d(again, {.delta = 0.05});
  RandomStream rng(23);
  d.run(rng);
  EXPECT_EQ(again.x, bed.x);
  EXPECT_EQ(again.y, bed.y);
  Frame redeposited;
  again.to_frame(redeposited);
  expect_deposited(again);
  // The labels are found again, except where a disk touches more than two others and
  // another touching pair holds it as well (the contacts found at zero distance tie).
  for (Eigen::Index k = 0; k < redeposited.size(); ++k) {
    if (redeposited.table<std::int64_t>("supports")(k, 0) ==
            saved.table<std::int64_t>("supports")(k, 0) &&
        redeposited.table<std::int64_t>("supports")(k, 1) ==
            saved.table<std::int64_t>("supports")(k, 1)) {
      continue;
    }
    const auto i = static_cast<std::size_t>(k);
    int touching = 0;
    for (std::size_t j = 0; j < bed.size(); ++j) {
      if (j != i && distance(bed, i, j) < (bed.r[i] + bed.r[j]) * (1.0 + 1e-9)) ++touching;
    }
    if (bed.x[i] - bed.r[i] < 1e-9 || bed.x[i] + bed.r[i] > bed.width - 1e-9) ++touching;
    EXPECT_GE(touching, 3) << "disk " << k << " changed its supports";
  }
}

TEST(Disks2dTapPacking, FromFrameRejectsWhatIsNotABedOfDisks) {
  dt::DiskPacking bed = random_bed(40, 10.0, 0.0, 24);
  Frame f;
  bed.to_frame(f);
  Frame three_d = f;
  three_d.dim = 3;
  EXPECT_THROW(dt::DiskPacking::from_frame(three_d, "f"), InputError);
  Frame shifted = f;
  shifted.container.lo.x() = -1.0;
  EXPECT_THROW(dt::DiskPacking::from_frame(shifted, "f"), InputError);
  // A base raised by 1.5 was read as one at y = 0, the disks on it left floating (exit 0).
  Frame raised = f;
  raised.container.lo.y() = 1.5;
  EXPECT_EQ(granpipe::test::input_error_of([&] { dt::DiskPacking::from_frame(raised, "f"); }),
            "f: expected a box whose left wall is at x = 0 and base at y = 0, at rest, got x = 0 "
            "and y = 1.5");
  Frame driven = f;
  driven.container.wall_offset.y() = 1.5;
  EXPECT_EQ(granpipe::test::input_error_of([&] { dt::DiskPacking::from_frame(driven, "f"); }),
            "f: expected a box whose left wall is at x = 0 and base at y = 0, at rest, got its "
            "walls displaced by (0, 1.5)");
  Frame periodic = f;  // was read as walled, exit 0
  periodic.container.boundary[0] = {granpipe::Boundary::Periodic, granpipe::Boundary::Periodic};
  EXPECT_EQ(granpipe::test::input_error_of([&] { dt::DiskPacking::from_frame(periodic, "f"); }),
            "f: expected a box with walls at x_low, x_high and y_low (the base), got periodic at "
            "x_low");
  Frame overlapping = f;
  overlapping.position().row(1) = overlapping.position().row(0);
  EXPECT_THROW(dt::DiskPacking::from_frame(overlapping, "f"), InputError);
  EXPECT_NO_THROW(dt::DiskPacking::from_frame(f, "f"));
}

TEST(Disks2dTapPlacement, PlacesWithoutOverlapOrSaysWhyNot) {
  RandomStream rng(12);
  const dt::DiskPacking p = dt::place_at_random(10.0, 30.0, std::vector<double>(60, kR), rng, "t");
  EXPECT_EQ(p.size(), 60u);
  EXPECT_NO_THROW(p.check("placed", 0.0));
  // A row of a box 2r + 0.1 high holds at most 10 / 2r = 6 disks.
  EXPECT_THROW(dt::place_at_random(10.0, 2 * kR + 0.1, std::vector<double>(7, kR), rng, "t", 200),
               InputError);
}

TEST(Disks2dTapSchedule, ConstantSavesEveryKthProductionTap) {
  const auto s = dt::TapSchedule::constant(1.2, 5, 20, 10);
  EXPECT_EQ(s.total(), 25);
  std::vector<std::int64_t> saved;
  for (std::int64_t t = 1; t <= s.total(); ++t) {
    EXPECT_EQ(s.at(t).amplitude, 1.2);
    if (s.at(t).save) saved.push_back(t);
  }
  EXPECT_EQ(saved, (std::vector<std::int64_t>{15, 25}));
}

TEST(Disks2dTapSchedule, CooledConstantStepsDownToAThenSavesAsConstant) {
  // From 1.3 down to 1.1 in steps of 0.05: levels 1.3, 1.25, 1.2, 1.15 (1.1 itself is A),
  // 4 taps each, none saved; then the constant schedule, its taps counted on.
  const auto s = dt::TapSchedule::cooled_constant(1.3, 0.05, 4, 1.1, 5, 20, 10);
  EXPECT_EQ(s.total(), 16 + 25);
  const double levels[] = {1.3, 1.25, 1.2, 1.15};
  for (std::int64_t t = 1; t <= 16; ++t) {
    EXPECT_NEAR(s.at(t).amplitude, levels[(t - 1) / 4], 1e-14);
    EXPECT_FALSE(s.at(t).save);
    EXPECT_EQ(s.at(t).cycle, -1);
  }
  const auto plain = dt::TapSchedule::constant(1.1, 5, 20, 10);
  for (std::int64_t t = 1; t <= plain.total(); ++t) {
    EXPECT_EQ(s.at(16 + t).amplitude, 1.1);
    EXPECT_EQ(s.at(16 + t).save, plain.at(t).save);
  }
  // A level a rounding error above A is A, not a cooling level: 1.3 -> 1.1 in 0.02 steps
  // visits 1.30 ... 1.12, ten levels.
  EXPECT_EQ(dt::TapSchedule::cooled_constant(1.3, 0.02, 1, 1.1, 0, 1, 1).total(), 10 + 1);
}

TEST(Disks2dTapSchedule, AnnealedRampsUpAndDown) {
  const auto s = dt::TapSchedule::annealed(1.0, 2.0, 4, 3, 2, 3);
  EXPECT_EQ(s.total(), 2 * 2 * 4 * 3);
  std::vector<double> amplitudes;
  std::vector<std::int64_t> cycles;
  int saves = 0;
  for (std::int64_t t = 1; t <= s.total(); t += 3) {
    amplitudes.push_back(s.at(t).amplitude);
    cycles.push_back(s.at(t).cycle);
    EXPECT_FALSE(s.at(t).save);
    EXPECT_TRUE(s.at(t + 2).save);  // the third tap of each step
  }
  for (std::int64_t t = 1; t <= s.total(); ++t) saves += s.at(t).save;
  EXPECT_EQ(saves, 16);
  EXPECT_EQ(amplitudes, (std::vector<double>{1.25, 1.5, 1.75, 2.0, 1.75, 1.5, 1.25, 1.0, 1.25, 1.5,
                                             1.75, 2.0, 1.75, 1.5, 1.25, 1.0}));
  EXPECT_EQ(cycles, (std::vector<std::int64_t>{0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3}));
}

TEST(Disks2dTapSchedule, RisingAndFallingRampsVisitTheSameAmplitudes) {
  // Bug: the rising ramp computed A_min + k dA and the falling one A_max - k dA, so A = 1.7
  // came out as 1.7000000000000002 going up and 1.7 going down, and tables keyed by A split.
  const std::int64_t steps = 20;
  const auto s = dt::TapSchedule::annealed(1.0, 2.0, steps, 1, 1, 1);
  for (std::int64_t k = 1; k < steps; ++k) {
    const double up = s.at(k).amplitude;                // level k on the way up
    const double down = s.at(2 * steps - k).amplitude;  // level k on the way down
    EXPECT_EQ(up, down) << "level " << k;
    EXPECT_NEAR(up, 1.0 + 0.05 * static_cast<double>(k), 1e-15);
  }
  EXPECT_EQ(s.at(steps).amplitude, 2.0);
  EXPECT_EQ(s.at(2 * steps).amplitude, 1.0);
}

namespace {

// The frames of the source made as a pipeline makes it: `params` over the schema's defaults.
std::vector<Frame> run_source(const nlohmann::json& params, std::uint64_t seed,
                              granpipe::Results* results = nullptr) {
  const auto ctx = granpipe::test::make_context(dt::schema(), params, seed);
  dt::TapSource source(*ctx);
  std::vector<Frame> frames;
  Frame f;
  while (source.next(f)) frames.push_back(f);
  if (results) source.finish(*results);
  return frames;
}

}  // namespace

// A parameter of the other protocol did nothing, without a word: the annealed run's A,
// the constant run's anneal_A_max, cool_step without cool_from; and mc_loops past 10^5.
TEST(Disks2dTapSource, ParametersThatWouldDoNothingOrTooMuchAreRefused) {
  const auto refusal = [](const nlohmann::json& params) {
    return granpipe::test::input_error_of([&] { run_source(params, 1); });
  };
  EXPECT_EQ(refusal({{"protocol", "annealed"}, {"A", 1.7}}),
            "test: params.A: expected its default 1.1 (it acts only with protocol \"constant\"; "
            "here protocol is \"annealed\"), got 1.7");
  EXPECT_EQ(refusal({{"anneal_A_max", 3.0}}),
            "test: params.anneal_A_max: expected its default 2 (it acts only with protocol "
            "\"annealed\"; here protocol is \"constant\"), got 3.0");
  EXPECT_EQ(refusal({{"cool_step", 0.05}}),
            "test: params.cool_step: expected its default 0.02 (it acts only with cool_from > 0; "
            "here cool_from is 0), got 0.05");
  // The shaker's grid is as tall as the loops could lift a disk: 10^8 took gigabytes.
  EXPECT_EQ(refusal({{"mc_loops", 100000000}}),
            "test: params.mc_loops: expected an integer in [0, 100000], got 100000000");
}

// Tap counts made of parameters wrapped round past 2^63: 2^63 - 1 production taps
// counted -2^63 in all and ran none (every result NaN, exit 0); cool_from 1e300 or a
// cool_step of 1e-320 skipped the cooling without a word.
TEST(Disks2dTapSource, TapCountsPastWhatCanBeCountedAreRefused) {
  const auto refusal = [](const nlohmann::json& params) {
    return granpipe::test::input_error_of([&] { run_source(params, 1); });
  };
  const auto most = std::numeric_limits<std::int64_t>::max();
  EXPECT_EQ(refusal({{"production_taps", most}}),
            "params.production_taps: expected fewer than 9007199254740992 taps, got "
            "9.22337e+18 (cooling levels x cool_taps_per_step + equilibration_taps + "
            "production_taps)");
  EXPECT_EQ(refusal({{"cool_from", 1.3}, {"cool_step", 1e-320}}),
            "params.cool_step: expected fewer than 9007199254740992 cooling levels, got inf "
            "((cool_from - A) / cool_step)");
  // Each names the parameter that made the count absurd (cool_step and production_taps
  // were named for these two).
  EXPECT_EQ(refusal({{"cool_from", 1e300}}),
            "params.cool_from: expected fewer than 9007199254740992 cooling levels, got 5e+301 "
            "((cool_from - A) / cool_step)");
  EXPECT_EQ(refusal({{"equilibration_taps", most}}),
            "params.equilibration_taps: expected fewer than 9007199254740992 taps, got "
            "9.22337e+18 (cooling levels x cool_taps_per_step + equilibration_taps + "
            "production_taps)");
  EXPECT_EQ(refusal({{"protocol", "annealed"}, {"anneal_cycles", most / 2}}),
            "params.anneal_cycles: expected fewer than 9007199254740992 taps, got "
            "1.84467e+22 (2 anneal_cycles x anneal_steps x anneal_taps_per_step)");
}

// A fall of 1e-320 left every coordinate as it was: the deposition never ended.
TEST(Disks2dTapSource, AFallLostInTheRoundingIsRefused) {
  const std::string refused = granpipe::test::input_error_of([&] {
    run_source(nlohmann::json({{"delta", 1e-320}}), 1);
  });
  EXPECT_EQ(refused.substr(0, refused.find(" (")),
            "params.delta: expected at least 1e-9 of the bed's size");
  EXPECT_EQ(refused.substr(refused.find("), ")),
            "), below which a fall is lost in the rounding of the coordinates, got 9.99989e-321");
}

TEST(Disks2dTapSource, SameSeedSameFrames) {
  const auto params = nlohmann::json({{"N", std::int64_t{120}},
                                      {"width", 10.0},
                                      {"delta", 0.05},
                                      {"equilibration_taps", std::int64_t{3}},
                                      {"production_taps", std::int64_t{4}},
                                      {"save_every", std::int64_t{2}},
                                      {"A", 1.3}});
  granpipe::Results results;
  const auto a = run_source(params, 77, &results), b = run_source(params, 77);
  const auto c = run_source(params, 78);
  auto other_replica = params;
  other_replica["replica"] = 1;
  const auto d = run_source(other_replica, 77);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].integer_observable("tap").value(), static_cast<std::int64_t>(5 + 2 * k));
    EXPECT_EQ(a[k].real_observable("amplitude").value(), 1.3);
    EXPECT_EQ(a[k].time, static_cast<double>(5 + 2 * k));  // time counts taps
    EXPECT_EQ(a[k].dim, 2);
    EXPECT_TRUE((a[k].position() == b[k].position()).all());
    EXPECT_TRUE(
        (a[k].table<std::int64_t>("supports") == b[k].table<std::int64_t>("supports")).all());
    EXPECT_FALSE((a[k].position() == c[k].position()).all());
    EXPECT_FALSE((a[k].position() == d[k].position()).all());
    EXPECT_NO_THROW(a[k].check("frame"));
  }
  EXPECT_EQ(results.scalar("taps").value, 7.0);
  EXPECT_EQ(results.scalar("moves").value,
            results.scalar("falls").value + results.scalar("rolls").value);
  EXPECT_GT(results.scalar("moves").value, 0.0);
}

// Without a Monte Carlo jump (mc_loops 0) the acceptance is 0/0: it was reported as 0.
TEST(Disks2dTapSource, TheAcceptanceOfNoJumpIsUndefined) {
  granpipe::Results results;
  run_source({{"N", std::int64_t{40}},
              {"width", 8.0},
              {"equilibration_taps", std::int64_t{0}},
              {"production_taps", std::int64_t{1}},
              {"save_every", std::int64_t{1}},
              {"mc_loops", std::int64_t{0}}},
             5, &results);
  EXPECT_TRUE(std::isnan(results.scalar("mc_acceptance").value));
}

TEST(Disks2dTapSource, ShuffledMonteCarloOrderIsReproducibleAndChangesTheRun) {
  auto params = [](const std::string& order) {
    return nlohmann::json({{"N", std::int64_t{120}},
                           {"width", 10.0},
                           {"delta", 0.05},
                           {"equilibration_taps", std::int64_t{2}},
                           {"production_taps", std::int64_t{2}},
                           {"save_every", std::int64_t{1}},
                           {"A", 1.2},
                           {"mc_order", order}});
  };
  const auto a = run_source(params("shuffled"), 21), b = run_source(params("shuffled"), 21);
  const auto by_index = run_source(params("index"), 21);
  ASSERT_EQ(a.size(), 2u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_TRUE((a[k].position() == b[k].position()).all());
    EXPECT_TRUE(
        (a[k].table<std::int64_t>("supports") == b[k].table<std::int64_t>("supports")).all());
    EXPECT_FALSE((a[k].position() == by_index[k].position()).all());
    EXPECT_NO_THROW(a[k].check("frame"));
  }
}

TEST(Disks2dTapSource, AnnealedFramesCarryCycleAndAmplitude) {
  const auto params = nlohmann::json({{"N", std::int64_t{60}},
                                      {"width", 8.0},
                                      {"delta", 0.05},
                                      {"protocol", std::string("annealed")},
                                      {"anneal_steps", std::int64_t{2}},
                                      {"anneal_taps_per_step", std::int64_t{1}},
                                      {"anneal_cycles", std::int64_t{1}},
                                      {"save_every", std::int64_t{1}},
                                      {"anneal_A_min", 1.0},
                                      {"anneal_A_max", 1.4}});
  const auto frames = run_source(params, 5);
  ASSERT_EQ(frames.size(), 4u);
  const double amplitudes[] = {1.2, 1.4, 1.2, 1.0};
  const std::int64_t cycles[] = {0, 0, 1, 1};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(frames[k].real_observable("amplitude").value(), amplitudes[k]);
    EXPECT_EQ(frames[k].integer_observable("cycle").value(), cycles[k]);
    EXPECT_EQ(frames[k].integer_observable("tap").value(), static_cast<std::int64_t>(k + 1));
  }
}

TEST(Disks2dTapSource, CoolsBeforeTheConstantTaps) {
  const auto params = nlohmann::json({{"N", std::int64_t{60}},
                                      {"width", 8.0},
                                      {"delta", 0.05},
                                      {"A", 1.1},
                                      {"cool_from", 1.3},
                                      {"cool_step", 0.1},
                                      {"cool_taps_per_step", std::int64_t{2}},
                                      {"equilibration_taps", std::int64_t{1}},
                                      {"production_taps", std::int64_t{2}},
                                      {"save_every", std::int64_t{1}}});
  granpipe::Results results;
  const auto frames = run_source(params, 9, &results);
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].integer_observable("tap").value(),
            6);  // 2 taps at 1.3 and 2 at 1.2, one to equilibrate
  EXPECT_EQ(frames[1].integer_observable("tap").value(), 7);
  EXPECT_EQ(frames[1].real_observable("amplitude").value(), 1.1);
  EXPECT_EQ(results.scalar("taps").value, 7.0);
}

TEST(Disks2dTapSource, RejectsImpossibleParameters) {
  EXPECT_THROW(run_source(nlohmann::json({{"delta", 0.9}}), 1), InputError);  // > radius
  EXPECT_THROW(run_source(nlohmann::json({{"width", 1.5}}), 1), InputError);  // disk too wide
  EXPECT_THROW(run_source(nlohmann::json({{"protocol", std::string("annealed")},
                                          {"anneal_A_min", 2.0},
                                          {"anneal_A_max", 1.5}}),
                          1),
               InputError);
  EXPECT_THROW(run_source(nlohmann::json({{"production_taps", std::int64_t{5}}}), 1), InputError);
  // Cooling must start above A.
  EXPECT_THROW(run_source(nlohmann::json({{"cool_from", 1.05}, {"A", 1.1}}), 1), InputError);
  // An annealed run whose steps are shorter than save_every would save nothing.
  EXPECT_THROW(run_source(nlohmann::json({{"protocol", std::string("annealed")},
                                          {"anneal_taps_per_step", std::int64_t{5}}}),
                          1),
               InputError);
}

// A box so wide that the simulation's grids would take gigabytes (a radius of 1e-200
// in a box of 20 is one) is refused before they are allocated.
TEST(Disks2dTapSource, WidthIsBoundedInDiametersBeforeAllocating) {
  try {
    run_source(nlohmann::json({{"width", 1e9}, {"radius", 0.5}}), 1);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "params.width: expected at most 1e+06 diameters of the smallest disk (1), got 1e+09");
  }
}

// A tap of amplitude 1e9 or an initial fraction of 1e-9 spreads the disks over a height a
// grid of disk-sized cells cannot cover: an internal error, exit 1 ("cannot create
// std::vector larger than max_size()"), or gigabytes and minutes before it.
// The refusal names the parameter that spread them (it named none).
TEST(Disks2dTapSource, APackingSpreadTooThinIsRefused) {
  const std::string grid = "expected a packing that a grid of at most 2^28 cells of side ";
  for (const auto& [params, named] :
       {std::pair{nlohmann::json({{"initial_fraction", 1e-9}}),
                  std::string("params.initial_fraction: ")},
        std::pair{nlohmann::json({{"A", 1e9}, {"equilibration_taps", 1}}),
                  std::string("params.A: tap 1 of amplitude 1e+09: ")}}) {
    const std::string m = granpipe::test::input_error_of([&] { run_source(params, 1); });
    EXPECT_EQ(m.substr(0, named.size() + grid.size()), named + grid) << m;
    EXPECT_NE(m.find("spread too thin for disks of these sizes"), std::string::npos) << m;
  }
}

// The largest initial fraction the schema allows must be one the placement reaches (0.5
// did not: at width 20 the centres reach 92 % of the width and the placement jammed).
TEST(Disks2dTapSource, PlacesAtTheLargestAllowedInitialFraction) {
  double largest = 0.0;
  const granpipe::Schema schema = dt::schema();
  for (const auto& spec : schema.specs())
    if (spec.name == "initial_fraction") largest = *spec.max;
  ASSERT_GT(largest, 0.0);
  for (const std::uint64_t seed : {1, 2, 3}) {
    for (const auto& [n, spread] : {std::pair{std::int64_t{2000}, 0.0}, {std::int64_t{500}, 0.5}}) {
      const auto params = nlohmann::json({{"N", n},
                                          {"radius_spread", spread},
                                          {"initial_fraction", largest},
                                          {"equilibration_taps", std::int64_t{0}},
                                          {"production_taps", std::int64_t{1}},
                                          {"save_every", std::int64_t{1}},
                                          {"A", 1.02}});
      const auto frames = run_source(params, seed);
      ASSERT_EQ(frames.size(), 1u);
      EXPECT_EQ(frames[0].size(), n);
    }
  }
}

// Without initial_file, initial_frame would change nothing: a start meant to continue a
// run would silently begin a new one.
TEST(Disks2dTapSource, AStartFrameWithoutAFileIsRefused) {
  EXPECT_EQ(granpipe::test::input_error_of([&] {
              run_source(nlohmann::json({{"N", 80}, {"initial_frame", 0}}), 3);
            }),
            "params.initial_frame: expected it only with initial_file (a frame of that "
            "file), got 0 without one");
}

TEST(Disks2dTapSource, StartsFromAFrameOfASavedFile) {
  const fs::path dir =
      fs::temp_directory_path() / ("granpipe_disks2d_tap_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // A polydisperse bed saved by one run...
  const auto saved = run_source(nlohmann::json({{"N", std::int64_t{80}},
                                                {"width", 9.0},
                                                {"delta", 0.05},
                                                {"radius_spread", 0.3},
                                                {"equilibration_taps", std::int64_t{0}},
                                                {"production_taps", std::int64_t{2}},
                                                {"save_every", std::int64_t{1}},
                                                {"A", 1.2}}),
                                3);
  const fs::path file = dir / "bed.h5";
  {
    granpipe::FrameWriter w(file, "{}");
    for (const Frame& f : saved) w.append(f);
    w.close();
  }
  // ...is what a monodisperse run started from it taps: the file's radii, not its own.
  const auto from_file = [&](const nlohmann::json& extra) {
    nlohmann::json params{{"initial_file", file.string()},
                          {"N", 80},
                          {"width", 9.0},
                          {"delta", 0.05},
                          {"equilibration_taps", 0},
                          {"production_taps", 1},
                          {"save_every", 1}};
    params.update(extra);
    return run_source(params, 4);
  };
  for (const std::int64_t frame : {std::int64_t{0}, std::int64_t{-1}}) {
    const auto frames = from_file({{"initial_frame", frame}});
    ASSERT_EQ(frames.size(), 1u);
    EXPECT_TRUE((frames[0].radius() == saved[0].radius()).all());
    EXPECT_FALSE((frames[0].radius() == kR).all());
    EXPECT_NO_THROW(frames[0].check("frame"));
  }
  EXPECT_THROW(from_file({{"initial_frame", std::int64_t{2}}}), InputError);  // the file holds 2
  EXPECT_THROW(from_file({{"N", std::int64_t{81}}}), InputError);
  EXPECT_THROW(from_file({{"width", 9.5}}), InputError);
  // The random placement's settings did nothing here, without a word.
  EXPECT_EQ(granpipe::test::input_error_of([&] {
              from_file({{"radius_spread", 0.3}});
            }),
            "test: params.radius_spread: expected its default 0 (it acts only with initial_file "
            "\"\"; here initial_file is \"" +
                file.string() + "\"), got 0.3");
  EXPECT_EQ(granpipe::test::input_error_of([&] {
              from_file({{"initial_fraction", 0.2}});
            }),
            "test: params.initial_fraction: expected its default 0.3 (it acts only with "
            "initial_file \"\"; here initial_file is \"" +
                file.string() + "\"), got 0.2");
  // Nor did a radius: the file stores the disks' own.
  EXPECT_EQ(granpipe::test::input_error_of([&] {
              from_file({{"radius", 2.0}});
            }),
            "params.radius: expected its default 0.80710678118654744 with an initial_file that "
            "stores radii "
            "(params.initial_file: " +
                file.string() + ": frame 1), got 2");
  fs::remove_all(dir);
}
