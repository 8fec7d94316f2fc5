// The stereology analyzer: Eq. (7) recovered from a noisy synthetic profile, and a layered
// crystal measured exactly (its fraction in every zone, no change over identical frames).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <tuple>

#include "fermi_profile.hpp"
#include "granpipe/errors.hpp"
#include "plugin_harness.hpp"
#include "profile_measure.hpp"
#include "stereology_analyzer.hpp"

using namespace granpipe;
using namespace granpipe::stereology;

namespace {

constexpr double kPi = std::numbers::pi;

// A simple cubic crystal of unit spheres (cells of side 2), `layers` deep on the bottom,
// walls on every side, with a tap observable.
Frame cubic_layers(int cells, int layers, std::int64_t tap = 0) {
  Frame f;
  f.dim = 3;
  f.container.hi = Eigen::Vector3d(2.0 * cells, 2.0 * cells, 2.0 * layers + 5.0);
  f.resize(static_cast<Eigen::Index>(cells * cells * layers), 3);
  Eigen::Index k = 0;
  for (int z = 0; z < layers; ++z)
    for (int y = 0; y < cells; ++y)
      for (int x = 0; x < cells; ++x, ++k) {
        f.position().row(k) << 2.0 * x + 1.0, 2.0 * y + 1.0, 2.0 * z + 1.0;
        f.radius()[k] = 1.0;
      }
  f.set_observable(Property{"tap", Scope::Frame, ValueType::Integer, 1, "", "tap"}, tap);
  return f;
}

}  // namespace

TEST(FermiProfile, FitRecoversEq7FromANoisyProfile) {
  Eigen::VectorXd truth(kFermiParameters);
  truth << 0.60, 0.002, 2.5, 24.0;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> z, phi;
  for (int k = 0; k < 300; ++k) {
    z.push_back(0.05 + 0.1 * k);
    phi.push_back(fermi_model().value(truth, z.back()) + noise(rng));
  }
  const CurveFit fit = fit_fermi_profile(z, phi, 5.0);
  ASSERT_TRUE(fit.fitted()) << describe(fit.status);
  for (int q = 0; q < kFermiParameters; ++q) {
    EXPECT_NEAR(fit.value[q], truth[q], 3.0 * fit.error[q]) << kFermiNames[q];
    EXPECT_LT(fit.error[q], 0.1 * std::abs(truth[q]) + 1e-3) << kFermiNames[q];
  }
}

TEST(FermiProfile, GradientIsTheModelsDerivative) {
  Eigen::VectorXd p(kFermiParameters);
  p << 0.6, 0.01, 1.7, 10.0;
  for (double z : {2.0, 9.5, 10.0, 12.0, 40.0}) {
    const Eigen::VectorXd g = fermi_model().gradient(p, z);
    for (int q = 0; q < kFermiParameters; ++q) {
      Eigen::VectorXd hi = p, lo = p;
      hi[q] += 1e-6;
      lo[q] -= 1e-6;
      const double numeric = (fermi_model().value(hi, z) - fermi_model().value(lo, z)) / 2e-6;
      EXPECT_NEAR(g[q], numeric, 1e-7) << kFermiNames[q] << " at z = " << z;
    }
  }
}

TEST(ProfileMeasure, OfALayeredCrystalIsItsFractionEverywhere) {
  const Frame f = cubic_layers(8, 10);
  ProfileSettings s;
  s.step = 0.5;
  s.lateral_band = 4.0;
  const ProfileMeasurement m = measure_profiles(f, s);
  EXPECT_NEAR(m.global.phi_b, kPi / 6.0, 1e-13);
  // Bins of half a radius: pairs of bins sum to a half layer of the crystal's fraction.
  ASSERT_EQ(m.vertical.size(), 40u);
  for (std::size_t k = 0; k + 1 < m.vertical.size(); k += 2) {
    EXPECT_NEAR(0.5 * (m.vertical[k] + m.vertical[k + 1]), kPi / 6.0, 1e-13) << k;
  }
  // Heights 0..17 across x: whole cells of side 2 lie in bands of 4, and so on.
  EXPECT_NEAR(m.lateral, kPi / 6.0, 1e-13);
  EXPECT_NEAR(m.central, kPi / 6.0, 1e-13);
  EXPECT_DOUBLE_EQ(m.transversal_step, 0.5);
  ASSERT_EQ(m.transversal.size(), 32u);
  for (std::size_t k = 0; k < m.transversal.size(); k += 4) {
    double cell = 0.0;
    for (std::size_t j = k; j < k + 4; ++j) cell += m.transversal[j] / 4.0;
    EXPECT_NEAR(cell, kPi / 6.0, 1e-13) << k;
  }
}

// H is the centre height below which `fraction` of the centres lie: 0.14 of 50 is 7, but
// 0.14 * 50 is 7.000000000000001 in doubles, and H was the 8th centre (phi_c of the wrong
// bed, exit 0); so for 0.56 of 25 and ten more two-digit fractions.
TEST(ProfileMeasure, TheHeightOfAFractionOfTheCentresCountsWholeCentres) {
  ProfileSettings s;
  s.step = 0.5;
  s.lateral_band = 0.5;
  for (const auto& [layers, fraction, centre] :
       {std::tuple{50, 0.14, 7}, std::tuple{25, 0.56, 14}, std::tuple{10, 0.9, 9},
        std::tuple{10, 0.95, 10}, std::tuple{10, 0.05, 1}}) {
    s.global.fraction = fraction;
    const ProfileMeasurement m = measure_profiles(cubic_layers(1, layers), s);
    EXPECT_EQ(m.global.height_c, 2.0 * centre - 1.0) << fraction << " of " << layers;
  }
}

// A central zone 2e-10 R wide (lateral_band a hair under half the width) had the fraction
// of the rounding of the cuts around it: 0.05 where the plane holds pi / 4, exit 0. Under
// 0.001 R it is none; at 0.002 R, through the spheres' centres, the plane's pi / 4 less the
// thin slab's mean of x^2 (the disks' area pi (1 - x^2)).
TEST(ProfileMeasure, ACentralZoneTooNarrowToMeasureIsUndefined) {
  ProfileSettings s;
  s.step = 0.5;
  s.lateral_band = 4.9999999999;
  EXPECT_TRUE(std::isnan(measure_profiles(cubic_layers(5, 10), s).central));
  s.lateral_band = 4.999;
  const ProfileMeasurement m = measure_profiles(cubic_layers(5, 10), s);
  ASSERT_EQ(m.global.height_c, 17.0);  // eight whole layers of disks and half the ninth
  EXPECT_NEAR(m.central, kPi / 4.0 * (1.0 - 1e-6 / 3.0), 1e-9);
}

// A vibrated base: the walls displaced by the wall offset. The bed moved down with its base
// measures as it did at rest (phi_b was taken 0..4R above the rest place, exit 0).
TEST(ProfileMeasure, HeightsAreAboveTheBaseWhereItIsAtTheFrame) {
  const Frame rest = cubic_layers(4, 6);
  Frame moved = rest;
  moved.container.wall_offset = Eigen::Vector3d(0.0, 0.0, -3.0);
  moved.position().col(2) -= 3.0;
  ProfileSettings s;
  s.step = 0.5;
  s.lateral_band = 2.0;
  const ProfileMeasurement a = measure_profiles(rest, s), b = measure_profiles(moved, s);
  EXPECT_NEAR(b.global.phi_b, kPi / 6.0, 1e-13);
  EXPECT_NEAR(b.global.phi_c, a.global.phi_c, 1e-13);
  EXPECT_EQ(b.global.height_c, a.global.height_c);
  ASSERT_EQ(b.vertical.size(), a.vertical.size());
  for (std::size_t k = 0; k < a.vertical.size(); ++k)
    EXPECT_NEAR(b.vertical[k], a.vertical[k], 1e-13) << k;
  EXPECT_NEAR(b.central, a.central, 1e-13);
  EXPECT_NEAR(b.lateral, a.lateral, 1e-13);
}

TEST(StereologyAnalyzer, IdenticalFramesChangeNothingAndTheTapIsRecorded) {
  const auto ctx = granpipe::test::make_context(schema(), {{"step", 0.5}, {"lateral_band", 4.0}});
  StereologyAnalyzer a(*ctx);
  FrameCache cache;
  for (std::int64_t tap : {0, 10, 20}) a.consume(cubic_layers(8, 10, tap), cache);
  Results r;
  a.finish(r);
  EXPECT_EQ(r.scalar("frames").value, 3.0);
  EXPECT_NEAR(r.scalar("phi_b").value, kPi / 6.0, 1e-13);
  EXPECT_NEAR(r.scalar("phi_c").value, kPi / 6.0 * (16.0 / 11.0 + 16.0) / 17.0, 1e-13);
  const Table& t = r.tables().at("per_frame");
  ASSERT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.column("tap")[2], 20.0);
  EXPECT_EQ(t.column("delta_lateral")[2], 0.0);
  EXPECT_EQ(t.column("delta_central")[2], 0.0);
  EXPECT_DOUBLE_EQ(t.column("height_c")[2], 17.0);
  const Table& v = r.tables().at("vertical_profile");
  EXPECT_EQ(v.rows(), 40u);
  EXPECT_EQ(v.column("phi_first")[3], v.column("phi_last")[3]);
}

// perturbed_factor had no bound: 1e300 gave phi_c 1.9e298, exit 0. The bottom layer of the
// cubic crystal fills pi/6 of its slab: a factor of 1.9 leaves it below 1, 2 does not.
TEST(StereologyAnalyzer, ACorrectionThatOverfillsTheBottomLayerIsRefused) {
  StereologySettings s;
  s.perturbed_factor = 1.9;
  EXPECT_LT(global_fractions(cubic_layers(8, 10), s).phi_c, 1.0);
  s.perturbed_factor = 2.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { global_fractions(cubic_layers(8, 10), s); }),
            "perturbed_factor: expected a correction that leaves the bottom layer's "
            "fraction at most 1, got 2, which makes it 1.0472");
}

// The factor's refusals named "perturbed_factor" without its path; a factor given with no
// layer to correct (perturbed_top 0) was taken without a word.
TEST(StereologyAnalyzer, ThePerturbedFactorIsNamedByItsPathAndNeedsALayer) {
  EXPECT_EQ(
      granpipe::test::input_error_of([] {
        granpipe::test::make_context(schema(), {{"perturbed_top", 0.0}, {"perturbed_factor", 2}});
      }),
      "test: params.perturbed_factor: expected its default 0 (it acts only with "
      "perturbed_top > 0; here perturbed_top is 0), got 2");
  Frame disks;
  disks.dim = 2;
  disks.container.hi = Eigen::Vector3d(8.0, 10.0, 0.0);
  disks.resize(4, 2);
  disks.radius().setConstant(1.0);
  disks.position() << 1, 1, 3, 1, 5, 1, 7, 1;
  const auto ctx = granpipe::test::make_context(schema(), {});
  StereologyAnalyzer a(*ctx);
  FrameCache cache;
  EXPECT_EQ(granpipe::test::input_error_of([&] { a.consume(disks, cache); }),
            "params.perturbed_factor: expected a factor for disks (the paper's 16/11 is for "
            "spheres on a plane; 1: no correction), got 0 (the paper's value, which has none "
            "for disks)");
}

// A centre beyond an open side was left out of phi, and counted in H and <Z> (exit 0).
TEST(StereologyAnalyzer, ACentreBeyondAnOpenSideIsRefused) {
  Frame f = cubic_layers(4, 3);
  f.container.boundary[0] = {Boundary::Open, Boundary::Open};
  EXPECT_NEAR(global_fractions(f, {}).phi_b, kPi / 6.0, 1e-13);
  f.position()(5, 0) = -3.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { global_fractions(f, {}); }),
            "particle 5: expected its centre within the open sides along x (0 to 8), where the "
            "cuts are, got -3");
  // Beyond a wall it is a frame's own refusal; beyond a periodic side it is an image.
  f.container.boundary[0] = {Boundary::Periodic, Boundary::Periodic};
  EXPECT_NO_THROW(global_fractions(f, {}));
}

// perturbed_top 0 (no corrected layer) gave phi_c NaN, blamed on a zone "not above" it.
// The cubic crystal's fraction up to height_c (17 R) is then its own, pi/6.
TEST(StereologyAnalyzer, NoPerturbedLayerLeavesPhiCUncorrected) {
  StereologySettings s;
  s.perturbed_top = 0.0;
  EXPECT_NEAR(global_fractions(cubic_layers(8, 10), s).phi_c, kPi / 6.0, 1e-13);
}

TEST(StereologyAnalyzer, ACylinderIsRefused) {
  const auto ctx = granpipe::test::make_context(schema());
  StereologyAnalyzer a(*ctx);
  FrameCache cache;
  Frame f = cubic_layers(2, 2);
  f.container.shape = ContainerShape::Cylinder;
  EXPECT_THROW(a.consume(f, cache), InputError);
}

// A step far too small for the bed asked for more bins than an int counts: the count
// wrapped around to a one-bin profile, exit 0. It is refused before anything is cut.
TEST(ProfileMeasure, AStepTooSmallForTheBedIsRefused) {
  ProfileSettings s;
  s.step = 1e-12;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure_profiles(cubic_layers(8, 10), s); }),
            "stereology.step: expected at most 10000000 bins of the vertical profile, got "
            "2e+13 (20 in steps of 1e-12)");
}

// A step of 1000 R made one bin from the base to 1000 R, its centre far above the bed.
TEST(ProfileMeasure, AStepPastTheBedOrTheBoxIsRefused) {
  ProfileSettings s;
  s.step = 1000.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure_profiles(cubic_layers(8, 10), s); }),
            "stereology.step: expected at most the bed's height in radii (20), got 1000: a "
            "single bin would reach past it");
  s.step = 19.0;
  EXPECT_EQ(granpipe::test::input_error_of([&] { measure_profiles(cubic_layers(8, 10), s); }),
            "stereology.step: expected at most the box's width in radii (16), got 19: a single "
            "bin would reach past it");
}

// The analyzer names the step where the pipeline has it ("analyzers[2].params.step"; the
// harness's "params.step"), not "stereology.step" whatever its name and place. A step
// below 1e-3 R is refused up front: the bins are counted per frame, and 3.6e-6 passed the
// first frame of a run to be refused at a taller one.
TEST(StereologyAnalyzer, AStepTooSmallIsNamedWhereThePipelineHasIt) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              granpipe::test::make_context(schema(), {{"step", 1e-12}});
            }),
            "test: params.step: expected a number >= 0.001, got 1e-12");
  EXPECT_EQ(granpipe::test::input_error_of([] {
              granpipe::test::make_context(schema(), {{"lateral_band", 1e-9}});
            }),
            "test: params.lateral_band: expected a number >= 0.001, got 1e-09");
  const auto ctx = granpipe::test::make_context(schema(), {{"step", 1e-3}});
  StereologyAnalyzer a(*ctx);
  FrameCache cache;
  EXPECT_EQ(granpipe::test::input_error_of([&] { a.consume(cubic_layers(1, 5001), cache); }),
            "params.step: expected at most 10000000 bins of the vertical profile, got "
            "1.0002e+07 (10002 in steps of 0.001)");
}

// A bed lower than bulk_top and a box no wider than two lateral bands: phi_b was the
// fraction of a slab partly empty and phi_central NaN, both with exit 0 and no word. phi_b
// is NaN now, left out of the mean as phi_c is, and the first such frame says why.
TEST(StereologyAnalyzer, UndefinedFractionsAreNaNAndSaidOnce) {
  const auto ctx = granpipe::test::make_context(schema(), {{"bulk_top", 40.0}});
  ctx->keep_log();
  StereologyAnalyzer a(*ctx);
  FrameCache cache;
  for (std::int64_t tap : {0, 10}) a.consume(cubic_layers(4, 10, tap), cache);
  Results r;
  a.finish(r);
  EXPECT_TRUE(std::isnan(r.scalar("phi_b").value));
  EXPECT_TRUE(std::isnan(r.scalar("phi_b_last").value));
  EXPECT_TRUE(std::isnan(r.scalar("phi_central").value));
  EXPECT_NEAR(r.scalar("phi_c").value, kPi / 6.0 * (16.0 / 11.0 + 16.0) / 17.0, 1e-13);
  granpipe::test::expect_said_once(
      ctx->logged_lines(),
      "warning: stereology: frame 0 (step 0): phi_b is undefined (NaN): bulk_top, 40 R, "
      "reaches above the highest particle top, 20 R; phi_central is undefined (NaN): the "
      "box leaves less than 0.001 R beside two bands of lateral_band, 7 R; said for the first "
      "such frame only",
      "undefined (NaN)");
}
