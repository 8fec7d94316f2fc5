// The 3D tapping model's sequential deposition against exact geometry: stops at contact,
// rests on three supports or the bottom, no overlap, and the known packing fraction.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "deposit.hpp"
#include "descent.hpp"
#include "epsilon_protocol.hpp"
#include "granpipe/container.hpp"
#include "granpipe/frame.hpp"
#include "neighbour_lists.hpp"
#include "plugin_harness.hpp"
#include "redeposition.hpp"
#include "saved_packing.hpp"
#include "sphere_grid.hpp"
#include "tap_schedule.hpp"
#include "trial_move.hpp"

namespace granpipe::spheres3d_tap {
namespace {

constexpr double kR = 1.0;

TapBox box(double side, Sides sides) { return TapBox{side, kR, sides}; }

// Minimum-image separation b - a on the box.
Eigen::Vector3d separation(const TapBox& b, const Eigen::Vector3d& from,
                           const Eigen::Vector3d& to) {
  Eigen::Vector3d d = to - from;
  if (b.periodic())
    for (int a = 0; a < 2; ++a) d[a] -= b.side * std::round(d[a] / b.side);
  return d;
}

TEST(Deposition, ASphereDroppedAloneRestsOnTheBottom) {
  Deposition deposition(box(10.0, Sides::Walls));
  RandomStream rng(1);
  deposition.drop(4.0, 6.0, rng);
  EXPECT_EQ(deposition.centres()[0], Eigen::Vector3d(4.0, 6.0, kR));
  EXPECT_EQ(deposition.supports()[0][0], partner::wall(Wall::ZLow));
}

TEST(Deposition, ASphereDroppedOnTopOfAnotherRollsOffOverItsEquatorToTheBottom) {
  Deposition deposition(box(20.0, Sides::Walls));
  RandomStream rng(7);
  deposition.drop(10.0, 10.0, rng);
  deposition.drop(10.0, 10.0, rng);  // exactly above: unstable balance, rolls off
  const Eigen::Vector3d& a = deposition.centres()[0];
  const Eigen::Vector3d& b = deposition.centres()[1];
  EXPECT_NEAR(b.z(), kR, 1e-12);
  EXPECT_NEAR((b - a).norm(), 2.0 * kR, 1e-12);  // left at the equator, fell straight down
}

TEST(Deposition, ASphereOnTwoTouchingSpheresRollsDownTheirGrooveToTheBottom) {
  Deposition deposition(box(20.0, Sides::Walls));
  RandomStream rng(3);
  deposition.drop(9.0, 10.0, rng);
  deposition.drop(11.0, 10.0, rng);
  deposition.drop(10.2, 10.3, rng);
  const auto& c = deposition.centres();
  EXPECT_NEAR(c[2].z(), kR, 1e-12);
  EXPECT_NEAR((c[2] - c[0]).norm(), 2.0 * kR, 1e-12);
  EXPECT_NEAR((c[2] - c[1]).norm(), 2.0 * kR, 1e-12);
  EXPECT_GT(c[2].y(), 10.0);  // on the side it was dropped
}

TEST(Deposition, ASphereOverATriangleOfThreeRestsAtTheTetrahedronApex) {
  Deposition deposition(box(20.0, Sides::Walls));
  RandomStream rng(5);
  const double h = std::sqrt(3.0) * kR;  // height of the triangle of side 2R
  deposition.drop(9.0, 9.0, rng);
  deposition.drop(11.0, 9.0, rng);
  deposition.drop(10.0, 9.0 + h, rng);
  deposition.drop(10.05, 9.0 + h / 3.0 - 0.1, rng);
  const Eigen::Vector3d apex(10.0, 9.0 + h / 3.0, kR + 2.0 * kR * std::sqrt(2.0 / 3.0));
  EXPECT_NEAR((deposition.centres()[3] - apex).norm(), 0.0, 1e-12);
  for (std::int64_t s : deposition.supports()[3]) EXPECT_TRUE(s >= 0 && s < 3);
}

TEST(Deposition, ASphereFallingBesideAWallSlidesDownItAndRollsOffAwayFromIt) {
  // Two spheres along the wall, touching it; the third drops in the wall's plane onto
  // their groove and would balance there on two: it rolls off away from the wall.
  Deposition deposition(box(20.0, Sides::Walls));
  RandomStream rng(11);
  deposition.drop(kR, 9.0, rng);
  deposition.drop(kR, 11.0, rng);
  deposition.drop(kR, 10.0, rng);
  const auto& c = deposition.centres();
  EXPECT_NEAR(c[2].z(), kR, 1e-12);
  EXPECT_GT(c[2].x(), kR + 1.0);
}

// Found in a deposition of 20000 spheres (walls, L = 52 R): a sphere on two spheres and the
// x = L - R wall, at rest, whose solve left a direction of 5e-12 pointing up. Taken for a
// descent it rolled the sphere uphill, it fell back to the same rest, and round again until
// the deposition gave up with an internal error. Coordinates as they were, to the bit.
TEST(Deposition, ASphereOnTwoSpheresAndAWallIsAtRestDespiteRounding) {
  const TapBox b = box(52.0, Sides::Walls);
  const Eigen::Vector3d p(51.0, 5.935084711835855, 34.547310374217204);
  std::vector<Obstacle> touching{
      Obstacle::of_sphere(12962, {51.0, 3.9394377960262936, 34.679194366497491}),
      Obstacle::of_sphere(12552, {49.525778067774461, 7.2828317561485418, 34.446079948496411})};
  for (const auto& plane : b.centre_planes())
    if (plane.label == static_cast<int>(Wall::XHigh)) touching.push_back(Obstacle::of_plane(plane));
  ASSERT_EQ(touching.size(), 3u);
  const Descent d = descend(p, touching);
  EXPECT_TRUE(d.direction.isZero(0.0)) << d.direction.transpose();
  EXPECT_EQ(d.supports.size(), 3u);
}

// Forces on the supports of a sphere at rest, found independently of the deposition:
// weight balanced by contact forces along the supports' normals, all pushing.
bool held_by(const TapBox& b, const std::vector<Eigen::Vector3d>& c, std::size_t i,
             const Supports& s) {
  Eigen::Matrix3d normals;
  for (int k = 0; k < 3; ++k) {
    if (partner::is_particle(s[k])) {
      const Eigen::Vector3d d = separation(b, c[static_cast<std::size_t>(s[k])], c[i]);
      EXPECT_NEAR(d.norm(), 2.0 * kR, 1e-9 * kR) << "sphere " << i << " support " << s[k];
      normals.col(k) = d.normalized();
    } else {
      const Wall w = partner::wall_of(s[k]);
      const int axis = w == Wall::XLow || w == Wall::XHigh ? 0 : 1;
      const bool low = w == Wall::XLow || w == Wall::YLow;
      EXPECT_NEAR(c[i][axis], low ? kR : b.side - kR, 1e-9 * kR) << "sphere " << i;
      normals.col(k) = (low ? 1.0 : -1.0) * Eigen::Vector3d::Unit(axis);
    }
  }
  const Eigen::Vector3d force = normals.fullPivLu().solve(Eigen::Vector3d::UnitZ());
  return (normals * force - Eigen::Vector3d::UnitZ()).norm() < 1e-9 &&
         (force.array() > -1e-12).all();
}

void expect_deposited_packing(const TapBox& b, int n, std::uint64_t seed) {
  Deposition deposition(b);
  RandomStream rng(seed);
  deposition.drop_random(n, rng);
  const auto& c = deposition.centres();
  for (std::size_t i = 0; i < c.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j)
      ASSERT_GE(separation(b, c[i], c[j]).norm(), 2.0 * kR * (1.0 - 1e-9)) << i << " " << j;
    const Supports& s = deposition.supports()[i];
    if (s[0] == partner::wall(Wall::ZLow)) {
      EXPECT_NEAR(c[i].z(), kR, 1e-9 * kR);
      continue;
    }
    ASSERT_NE(s[2], partner::none)
        << "sphere " << i << " off the bottom with fewer than three supports";
    EXPECT_TRUE(held_by(b, c, i, s)) << "sphere " << i;
  }
}

TEST(Deposition, EverySphereRestsOnThreeSupportsOrTheBottomWithoutOverlapPeriodic) {
  expect_deposited_packing(box(8.0, Sides::Periodic), 400, 21);
}

TEST(Deposition, EverySphereRestsOnThreeSupportsOrTheBottomWithoutOverlapWalls) {
  expect_deposited_packing(box(8.0, Sides::Walls), 400, 22);
}

// The volume of a sphere of radius r centred at z between heights lo and hi.
double slab_volume(double z, double r, double lo, double hi) {
  auto below = [&](double h) {  // volume under height h
    const double t = std::clamp(h - (z - r), 0.0, 2.0 * r);
    return std::numbers::pi * t * t * (3.0 * r - t) / 3.0;
  };
  return below(hi) - below(lo);
}

TEST(Deposition, APeriodicDepositionFillsFiftyEightPerCentOfTheBulk) {
  // Random deposition with rolling to three supports packs at about 0.58 (Jullien &
  // Meakin; the paper's initial packing 58.4 %), away from the bottom and the surface.
  const TapBox b = box(16.0, Sides::Periodic);
  Deposition deposition(b);
  RandomStream rng(2026);
  deposition.drop_random(2000, rng);
  double volume = 0.0;
  const double lo = 6.0 * kR, hi = 26.0 * kR;
  for (const auto& c : deposition.centres()) volume += slab_volume(c.z(), kR, lo, hi);
  const double phi = volume / (b.side * b.side * (hi - lo));
  EXPECT_NEAR(phi, 0.582, 0.01);
}

TEST(Deposition, TheSameSeedGivesTheSameBits) {
  auto run = [] {
    Deposition deposition(box(8.0, Sides::Periodic));
    RandomStream rng(9);
    deposition.drop_random(200, rng);
    return deposition.centres();
  };
  EXPECT_EQ(run(), run());
}

// Pearson's chi^2 of counts against expected counts.
double chi2(const std::vector<double>& counts, const std::vector<double>& expected) {
  double sum = 0.0;
  for (std::size_t k = 0; k < counts.size(); ++k)
    sum += std::pow(counts[k] - expected[k], 2) / expected[k];
  return sum;
}
// chi^2 above this for 19 degrees of freedom happens with probability 0.001.
constexpr double kChi2Critical19 = 43.82;
constexpr int kBins = 20;

// Counts of the polar angle theta in kBins bins of [0, pi/2] against Eq. (1)'s density
// exp(-(t/t0)^2) integrated over each bin: (sqrt(pi)/2) t0 (erf(b/t0) - erf(a/t0)).
double polar_chi2(const std::vector<double>& thetas, double theta0) {
  const double width = std::numbers::pi / 2.0 / kBins;
  std::vector<double> counts(kBins, 0.0), expected(kBins, 0.0);
  for (double t : thetas) counts[std::min(kBins - 1, static_cast<int>(t / width))] += 1.0;
  double total = 0.0;
  for (int b = 0; b < kBins; ++b) {
    expected[b] = std::erf((b + 1) * width / theta0) - std::erf(b * width / theta0);
    total += expected[b];
  }
  for (double& e : expected) e *= static_cast<double>(thetas.size()) / total;
  return chi2(counts, expected);
}

TEST(TrialMove, ThePolarAngleHasTheDensityOfEquationOneTruncatedAtNinetyDegrees) {
  // Both the angle drawn and the angle of the displacement vector, whose sines and
  // cosines come from tables and series: each against the density, for the paper's
  // width and a narrower one (whose envelope falls a hundredfold over the strips).
  for (double theta0 : {std::numbers::pi / 4.0, 0.6}) {
    const TrialMove move(0.2, theta0);
    FastRandomStream rng(31);
    std::vector<double> drawn, of_vector;
    for (int k = 0; k < 200000; ++k) {
      drawn.push_back(move.polar(rng));
      const Eigen::Vector3d d = move.draw(rng);
      of_vector.push_back(std::acos(std::clamp(-d.z() / d.norm(), -1.0, 1.0)));
    }
    EXPECT_LT(polar_chi2(drawn, theta0), kChi2Critical19) << theta0;
    EXPECT_LT(polar_chi2(of_vector, theta0), kChi2Critical19) << theta0;
  }
}

TEST(TrialMove, SinesAndCosinesAreExactToRounding) {
  // |d| is the drawn length to rounding only if sin^2 + cos^2 = 1 for both angles: the
  // length is uniform, so |d| / d_max spread over [0, 1) with no point above 1.
  const TrialMove move(1.0, std::numbers::pi / 4.0);
  FastRandomStream a(33), b(33);
  for (int k = 0; k < 100000; ++k) {
    const double length = b.uniform();
    b.bits();  // the azimuth's draw
    move.polar(b);
    EXPECT_NEAR(move.draw(a).norm(), length, 4e-16);
  }
}

TEST(TrialMove, LengthAndAzimuthAreUniformAndNoMoveGoesUp) {
  const TrialMove move{0.2, std::numbers::pi / 4.0};
  FastRandomStream rng(32);
  const int n = 200000;
  std::vector<double> length(kBins, 0.0), azimuth(kBins, 0.0);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector3d d = move.draw(rng);
    ASSERT_LE(d.z(), 0.0);
    length[std::min(kBins - 1, static_cast<int>(d.norm() / move.d_max() * kBins))] += 1.0;
    const double phi = std::atan2(d.y(), d.x()) + std::numbers::pi;
    azimuth[std::min(kBins - 1, static_cast<int>(phi / (2.0 * std::numbers::pi) * kBins))] += 1.0;
  }
  const std::vector<double> flat(kBins, static_cast<double>(n) / kBins);
  EXPECT_LT(chi2(length, flat), kChi2Critical19);
  EXPECT_LT(chi2(azimuth, flat), kChi2Critical19);
}

std::vector<Eigen::Vector3d> deposited(const TapBox& b, int n, std::uint64_t seed) {
  Deposition deposition(b);
  RandomStream rng(seed);
  deposition.drop_random(n, rng);
  return deposition.centres();
}

double mean_z(const std::vector<Eigen::Vector3d>& c) {
  double sum = 0.0;
  for (const auto& x : c) sum += x.z();
  return sum / static_cast<double>(c.size());
}

// Contacts the deposition made are exact to rounding; nothing may come closer than that.
constexpr double kRounding = 1e-12 * kR;

void expect_no_overlap_inside(const TapBox& b, const std::vector<Eigen::Vector3d>& c) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    ASSERT_GE(c[i].z(), kR - kRounding);
    if (!b.periodic()) {
      for (int a = 0; a < 2; ++a) {
        ASSERT_GE(c[i][a], kR - kRounding);
        ASSERT_LE(c[i][a], b.side - kR + kRounding);
      }
    }
    for (std::size_t j = 0; j < i; ++j)
      ASSERT_GE(separation(b, c[i], c[j]).norm(), 2.0 * kR - kRounding) << i << " " << j;
  }
}

// The overlap test by the lists against all spheres' nearest images, over moves accepted
// by the brute-force test, in boxes wide and narrow (where a sphere's images crowd).
void expect_lists_agree_with_every_sphere(const TapBox& b, int n, std::uint64_t seed) {
  std::vector<Eigen::Vector3d> c = deposited(b, n, seed);
  const TrialMove move(0.3, 1.0);
  NeighbourLists lists(b, move.d_max(), 0.5 * move.d_max());
  FastRandomStream rng(seed + 1);
  int overlapping = 0, accepted = 0;
  for (int tap = 0; tap < 20; ++tap) {
    // Dilated, as by a tap: a packing at rest has no free downward move.
    for (auto& x : c) x.z() *= 1.1;
    SphereGrid grid(b);
    for (std::size_t i = 0; i < c.size(); ++i) grid.put(static_cast<std::int32_t>(i), c[i]);
    lists.rebuild(c, grid);
    for (int k = 0; k < 2000; ++k) {
      const auto i = static_cast<std::int32_t>(rng.below(c.size()));
      Eigen::Vector3d& x = c[static_cast<std::size_t>(i)];
      const Eigen::Vector3d t = x + move.draw(rng);
      bool any = false;
      for (std::size_t j = 0; j < c.size(); ++j)
        any |= j != static_cast<std::size_t>(i) && separation(b, t, c[j]).norm() < 2.0 * kR;
      ASSERT_EQ(lists.overlaps(i, t, c), any) << tap << " " << k;
      overlapping += any;
      const bool in_walls = b.periodic() || (t.x() >= kR && t.y() >= kR && t.x() <= b.side - kR &&
                                             t.y() <= b.side - kR);
      if (any || t.z() < kR || !in_walls) continue;
      grid.erase(x);
      x = b.wrap(t);
      grid.put(i, x);
      lists.moved(i, c, grid);
      ++accepted;
    }
  }
  // Both outcomes were tried many times, and lists were renewed along the way.
  EXPECT_GT(overlapping, 1000) << b.side;
  EXPECT_GT(accepted, 1000) << b.side;
  EXPECT_GT(lists.renewals(), 100u) << b.side;
}

TEST(NeighbourLists, ListTheWorstCaseAcrossAPeriodicSide) {
  // Two spheres just within reach = 2R + move + 2 slack of each other when listed, across
  // the periodic side at x = 0; each then strays by the slack towards the other (no
  // renewal yet) and i tries the longest move towards j: they overlap, and the lists know.
  const TapBox b = box(10.0, Sides::Periodic);
  const double move = 0.3, slack = 0.2, reach = 2.0 * kR + move + 2.0 * slack;
  std::vector<Eigen::Vector3d> c{{0.5, 5.0, 3.0}, b.wrap({0.5 - reach + 1e-9, 5.0, 3.0})};
  SphereGrid grid(b);
  for (std::int32_t i = 0; i < 2; ++i) grid.put(i, c[static_cast<std::size_t>(i)]);
  NeighbourLists lists(b, move, slack);
  lists.rebuild(c, grid);
  for (std::int32_t i = 0; i < 2; ++i) {
    const Eigen::Vector3d towards(i == 0 ? -slack : slack, 0.0, 0.0);
    grid.erase(c[static_cast<std::size_t>(i)]);
    c[static_cast<std::size_t>(i)] = b.wrap(c[static_cast<std::size_t>(i)] + towards);
    grid.put(i, c[static_cast<std::size_t>(i)]);
    lists.moved(i, c, grid);
  }
  EXPECT_EQ(lists.renewals(), 0u);
  const Eigen::Vector3d t = c[0] - Eigen::Vector3d(move, 0.0, 0.0);
  ASSERT_LT(separation(b, t, c[1]).norm(), 2.0 * kR);
  EXPECT_TRUE(lists.overlaps(0, t, c));
}

TEST(NeighbourLists, AgreeWithEverySphereAfterManyMoves) {
  expect_lists_agree_with_every_sphere(box(8.0, Sides::Periodic), 150, 51);
  expect_lists_agree_with_every_sphere(box(8.0, Sides::Walls), 150, 52);
  expect_lists_agree_with_every_sphere(box(2.5, Sides::Periodic), 12, 53);
  // Wider than a query, but not than the cells the query touches.
  expect_lists_agree_with_every_sphere(box(6.0, Sides::Periodic), 80, 54);
}

TEST(Redeposition, TapsLeaveNoOverlapAndNoSphereOutsideTheBox) {
  for (Sides sides : {Sides::Periodic, Sides::Walls}) {
    const TapBox b = box(8.0, sides);
    std::vector<Eigen::Vector3d> c = deposited(b, 250, 41);
    Redeposition redeposition(b, RedepositionOptions{TrialMove{}, 1e-4, 0, 1000});
    FastRandomStream rng(42);
    for (int tap = 0; tap < 3; ++tap) {
      const TapStats stats = redeposition.tap(c, 0.1, rng);
      EXPECT_GT(stats.accepted, 0);
      expect_no_overlap_inside(b, c);
    }
  }
}

// A tap in which no sphere could move met the stopping rule (no change of <Z>) and was
// counted settled, lifted by 1 + epsilon: a sphere held between walls one diameter apart
// can only move straight down, which no drawn move is.
TEST(Redeposition, ATapInWhichNoSphereMovedIsNotSettled) {
  const TapBox b = box(2.0 * kR, Sides::Walls);
  std::vector<Eigen::Vector3d> c{{kR, kR, 3.0 * kR}};
  Redeposition redeposition(b, RedepositionOptions{TrialMove{}, 1e-6, 0, 10});
  FastRandomStream rng(45);
  const TapStats stats = redeposition.tap(c, 0.1, rng);
  EXPECT_EQ(stats.accepted, 0);
  EXPECT_FALSE(stats.converged);
  EXPECT_DOUBLE_EQ(c[0].z(), 3.3 * kR);
}

// A check of one sweep is one trial for one sphere: a single refused trial left <Z> unchanged
// and passed for settled, and a lone sphere rose tap by tap (1.10 R after five). Each check
// now holds at least 64 trials: the sphere comes back to rest on the bottom every tap.
TEST(Redeposition, ALoneSphereComesBackToRestEveryTap) {
  const TapBox b = box(6.0, Sides::Walls);
  std::vector<Eigen::Vector3d> c{{3.0 * kR, 3.0 * kR, kR}};
  Redeposition redeposition(b, RedepositionOptions{});
  FastRandomStream rng(49);
  for (int tap = 0; tap < 20; ++tap) {
    const TapStats stats = redeposition.tap(c, 0.05, rng);
    EXPECT_TRUE(stats.converged) << tap;
    EXPECT_LT(c[0].z(), 1.01 * kR) << tap;
  }
}

TEST(Redeposition, TrialMovesNeverRaiseTheMeanHeight) {
  // Eq. (1) is truncated at theta = pi/2: no trial move goes up, so without a dilation
  // <Z> can only fall, and a dilated packing ends below its dilated height.
  const TapBox b = box(8.0, Sides::Periodic);
  std::vector<Eigen::Vector3d> c = deposited(b, 250, 43);
  Redeposition redeposition(b, RedepositionOptions{});
  FastRandomStream rng(44);
  double before = mean_z(c);
  redeposition.shake(c, 20000, rng);
  EXPECT_LE(mean_z(c), before);
  before = mean_z(c);
  redeposition.tap(c, 0.05, rng);
  EXPECT_LT(mean_z(c), 1.05 * before);
}

TEST(Redeposition, ATapWithoutDilationOnlySettlesThePacking) {
  // epsilon = 0: no sphere is lifted, so the redeposition can only lower <Z>, and the
  // deposited packing, already at rest, barely moves.
  const TapBox b = box(8.0, Sides::Walls);
  std::vector<Eigen::Vector3d> c = deposited(b, 250, 47);
  Redeposition redeposition(b, RedepositionOptions{});
  FastRandomStream rng(48);
  const double before = mean_z(c);
  const TapStats stats = redeposition.tap(c, 0.0, rng);
  EXPECT_TRUE(stats.converged);
  EXPECT_LE(mean_z(c), before);
  EXPECT_GT(mean_z(c), 0.99 * before);
  expect_no_overlap_inside(b, c);
}

TEST(Redeposition, TheSameSeedGivesTheSameBits) {
  const TapBox b = box(8.0, Sides::Walls);
  auto run = [&] {
    std::vector<Eigen::Vector3d> c = deposited(b, 150, 45);
    Redeposition redeposition(b, RedepositionOptions{TrialMove{}, 1e-4, 0, 100});
    FastRandomStream rng(46);
    redeposition.tap(c, 0.1, rng);
    return c;
  };
  EXPECT_EQ(run(), run());
}

TEST(SaveSchedule, SavesTenTapsPerDecadeAndEveryKth) {
  const SaveSchedule log_only{1000, true};
  std::vector<std::int64_t> saved;
  for (std::int64_t t = 0; t <= 100; ++t)
    if (log_only.saves(t)) saved.push_back(t);
  const std::vector<std::int64_t> expected{0,  1,  2,  3,  4,  6,  7,  8,  10, 13,
                                           16, 20, 26, 32, 40, 51, 64, 80, 100};
  EXPECT_EQ(saved, expected);
  const SaveSchedule every{25, false};
  for (std::int64_t t = 0; t <= 100; ++t) EXPECT_EQ(every.saves(t), t % 25 == 0) << t;
}

TEST(SaveSchedule, TheStartCanBeLeftOut) {
  const SaveSchedule tapped_only{50, false, false};
  EXPECT_FALSE(tapped_only.saves(0));
  EXPECT_FALSE(tapped_only.saves(1));
  EXPECT_TRUE(tapped_only.saves(50));
  EXPECT_TRUE((SaveSchedule{50, false, true}.saves(0)));
}

TEST(EpsilonProtocol, RampsStepTheRootUpDownAndUpAgainEndingEachStep) {
  // sqrt(epsilon) 0.1, 0.2, 0.3 up, 0.2, 0.1 down, 0.2, 0.3 up; two taps each.
  const EpsilonProtocol ramp = EpsilonProtocol::ramp(0.1, 0.3, 0.1, 2, 3);
  ASSERT_EQ(ramp.taps(), 14);
  const std::vector<double> roots{0.1, 0.2, 0.3, 0.2, 0.1, 0.2, 0.3};
  const std::vector<int> legs{0, 0, 0, 1, 1, 2, 2};
  for (std::int64_t tap = 1; tap <= ramp.taps(); ++tap) {
    const auto k = static_cast<std::size_t>((tap - 1) / 2);
    const EpsilonAt e = ramp.at(tap);
    EXPECT_NEAR(e.epsilon, roots[k] * roots[k], 1e-15) << tap;
    EXPECT_EQ(e.leg, legs[k]) << tap;
    EXPECT_EQ(e.ends_step, tap % 2 == 0) << tap;
  }
  const EpsilonProtocol constant = EpsilonProtocol::constant(0.05, 7);
  EXPECT_EQ(constant.taps(), 7);
  EXPECT_EQ(constant.at(3).epsilon, 0.05);
  EXPECT_EQ(constant.at(3).leg, -1);
}

// A saved start "f" of two spheres of radius kR in `b`'s container, at `centres` (a row
// each).
StartFrame two_spheres_in(const TapBox& b, const Eigen::Matrix<double, 2, 3>& centres) {
  Frame f;
  f.resize(2, 3);
  f.position() = centres.array();
  f.radius().setConstant(kR);
  f.container = b.container(10.0);
  StartFrame start;
  start.frame = std::move(f);
  start.where.assign(1, 'f');  // = "f" gave GCC 12 a false -Wrestrict
  return start;
}

// A start frame's own container was not compared with the model's box: a cylinder was run
// as the square around it, a base raised by a wall offset as one at z = 0 (the spheres
// left floating), a box periodic along x alone as a walled one; all with exit 0.
TEST(Spheres3dTapSavedStart, AContainerOtherThanTheModelsIsRefused) {
  const TapBox walled = box(6.0, Sides::Walls);
  StartFrame start =
      two_spheres_in(walled, (Eigen::Matrix<double, 2, 3>() << 1, 1, 1, 3, 1, 1).finished());
  Frame& f = start.frame;
  const auto refusal = [&](const auto& change) {
    const Frame kept = f;
    change(f.container);
    const std::string message = test::input_error_of([&] { read_saved_packing(start, walled, 2); });
    f = kept;
    return message;
  };
  EXPECT_EQ(read_saved_packing(start, walled, 2).centres.size(), 2u);
  const std::string expected =
      "f: expected a box [0, 6]^2 with wall sides over a bottom wall at z = 0, at rest, got ";
  EXPECT_EQ(refusal([](Container& c) {
              c.shape = ContainerShape::Cylinder;
              c.cylinder_center = {3, 3};
              c.cylinder_radius = 3.0;
            }),
            expected + "a cylinder container");
  EXPECT_EQ(refusal([](Container& c) { c.wall_offset.z() = 2.5; }),
            expected + "its walls displaced by (0, 0, 2.5)");
  EXPECT_EQ(refusal([](Container& c) {
              c.boundary[0] = {Boundary::Periodic, Boundary::Periodic};
            }),
            expected + "periodic at x_low");
  EXPECT_EQ(refusal([](Container& c) { c.boundary[2][0] = Boundary::Open; }),
            expected + "open at z_low");
  EXPECT_EQ(refusal([](Container& c) { c.wall_velocity.z() = 0.5; }),
            expected + "its walls moving at (0, 0, 0.5)");
  // Another tool's H5MD file has a wall at the top (boundary "none"): no matter.
  f.container.boundary[2][1] = Boundary::Wall;
  EXPECT_EQ(read_saved_packing(start, walled, 2).centres.size(), 2u);
  EXPECT_EQ(refusal([](Container& c) { c.lo.z() = -1.0; }),
            expected + "[0, 6] x [0, 6] over a bottom at z = -1");
}

// Along periodic sides a saved sphere may be any image of itself: one 10 out along x,
// overlapping another once wrapped, passed (exit 0); one a whole period out ended in the
// grid ("two spheres in one cell", exit 1).
TEST(Spheres3dTapSavedStart, ImagesAlongPeriodicSidesAreCheckedWhereTheyWrap) {
  const TapBox periodic = box(6.0, Sides::Periodic);
  // The second wraps to 0.5 R from the first.
  StartFrame start = two_spheres_in(
      periodic,
      (Eigen::Matrix<double, 2, 3>() << 1, 1, kR, 1 + 6 + 0.5 * kR, 1 + 12, kR).finished());
  Frame& f = start.frame;
  EXPECT_EQ(test::input_error_of([&] {
              read_saved_packing(start, periodic, 2);
            }).rfind("f: spheres 0 and 1 overlap (centres ", 0),
            0u);
  f.position() << 1, 1, kR, 1 + 6, 1 - 6, kR;  // the first, one period out
  EXPECT_EQ(test::input_error_of([&] {
              read_saved_packing(start, periodic, 2);
            }).rfind("f: spheres 0 and 1 overlap (centres 0 apart", 0),
            0u);
  f.position() << 1, 1, kR, 4 + 60, 1, kR;
  const SavedPacking kept = read_saved_packing(start, periodic, 2);
  EXPECT_EQ(kept.centres[1].x(), 4.0);
}

}  // namespace
}  // namespace granpipe::spheres3d_tap
