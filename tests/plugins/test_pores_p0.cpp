// P0(sigma), the probability that a random probe sphere overlaps no sphere: Monte Carlo
// against exact answers (one sphere in a box, P0(0) = 1 - phi of a random gas and of a
// crystal) and the Percus-Yevick column against the formula written here in another form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "granpipe/errors.hpp"
#include "granpipe/frame.hpp"
#include "granpipe/random.hpp"
#include "granpipe/region.hpp"
#include "percus_yevick.hpp"
#include "plugin_harness.hpp"
#include "void_probability.hpp"
#include "void_probes.hpp"

namespace {

using granpipe::Frame;
using granpipe::RandomStream;
using granpipe::Region;
using granpipe::pores::p0_percus_yevick;
using granpipe::pores::probe_gaps;
using granpipe::pores::probe_region;
using granpipe::pores::VoidProbability;

Frame box_frame(long n, double side) {
  Frame f;
  f.resize(static_cast<Eigen::Index>(n), 3);
  f.radius().setConstant(1.0);
  f.container.lo.setConstant(0.0);
  f.container.hi.setConstant(side);
  return f;
}

// P0 of the frame's probes on the grid, and its table.
granpipe::Table p0_table(const Frame& f, long probes, double sigma_max, std::uint64_t seed) {
  const Region box = probe_region(f, std::nullopt, "test");
  RandomStream stream(seed);
  VoidProbability p0(0.25, sigma_max);
  p0.add(probe_gaps(f, box, probes, sigma_max, stream, "test"),
         granpipe::particle_measure_in(f, box), box.volume());
  return p0.table();
}

// One sphere of radius 1 in the middle of a box of side 10: a probe of radius sigma misses
// it outside the inflated sphere of radius 1 + sigma, P0 = 1 - 4/3 pi (1 + sigma)^3 / 1000.
TEST(PoresP0, OneSphereInABox) {
  Frame f = box_frame(1, 10.0);
  f.position().row(0) << 5, 5, 5;
  const granpipe::Table t = p0_table(f, 200000, 2.0, 7);
  const auto& sigma = t.column("sigma");
  ASSERT_EQ(sigma.size(), 9u);
  for (std::size_t k = 0; k < sigma.size(); ++k) {
    const double exact = 1.0 - 4.0 / 3.0 * M_PI * std::pow(1.0 + sigma[k], 3) / 1000.0;
    EXPECT_NEAR(t.column("P0")[k], exact, 4.0 * t.column("P0_err")[k] + 1e-12) << sigma[k];
  }
}

// The grid ran past sigma_max to the next multiple of the step (sigma_max 0.3, step 0.2:
// up to 0.4), the probes looking further than the parameter said.
TEST(PoresP0, TheGridEndsAtSigmaMax) {
  EXPECT_EQ(VoidProbability(0.2, 0.3).table().column("sigma"),
            (std::vector<double>{0.0, 0.2, 0.3}));
  EXPECT_EQ(VoidProbability(0.25, 1.0).table().column("sigma"),
            (std::vector<double>{0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_EQ(VoidProbability(0.5, 0.0).table().column("sigma"), (std::vector<double>{0.0}));
}

// Spheres placed at random without overlap in a periodic box: P0(0), the void fraction, is
// 1 - phi in expectation, phi the exact particle volume over the box's.
TEST(PoresP0, ZeroProbeFindsTheVoidFraction) {
  const double side = 12.0;
  Frame f = box_frame(60, side);
  f.container = granpipe::Container::periodic_box(3, {0, 0, 0}, {side, side, side});
  RandomStream place(3);
  for (Eigen::Index k = 0; k < f.size();) {
    const Eigen::Array3d x(place.uniform(0, side), place.uniform(0, side), place.uniform(0, side));
    bool free = true;
    for (Eigen::Index j = 0; j < k; ++j) {
      Eigen::Array3d d = x - f.position().row(j).transpose();
      for (int a = 0; a < 3; ++a) d[a] = f.container.minimum_image(a, d[a]);
      free = free && d.matrix().norm() >= 2.0;
    }
    if (free) f.position().row(k++) = x.transpose();
  }
  const double phi = 60 * 4.0 / 3.0 * M_PI / (side * side * side);
  const granpipe::Table t = p0_table(f, 100000, 1.0, 9);
  EXPECT_NEAR(t.column("P0")[0], 1.0 - phi, 4.0 * t.column("P0_err")[0]);
  EXPECT_NEAR(t.column("P0_py")[0], 1.0 - phi, 1e-12);
}

// The same prediction written in the paper's variable s = 1 + sigma (the distance from the
// probe's centre to the spheres' centres, in radii), expanded: ln(P0 / (1 - phi)) =
// phi/(1 - phi)^3 [-(1 + phi + phi^2) s^3 + 9/2 phi (1 + phi) s^2 - 9 phi^2 s
//                  + 1 - 7/2 phi + 11/2 phi^2].
TEST(PoresP0, PercusYevickAgreesWithItsExpandedForm) {
  for (double phi : {0.1, 0.584, 0.606}) {
    for (double sigma : {0.0, 0.1, 0.5, 1.0}) {
      const double s = 1.0 + sigma, h = 1.0 - phi;
      const double polynomial = -(1 + phi + phi * phi) * s * s * s + 4.5 * phi * (1 + phi) * s * s -
                                9 * phi * phi * s + 1 - 3.5 * phi + 5.5 * phi * phi;
      const double expected = h * std::exp(phi / (h * h * h) * polynomial);
      EXPECT_NEAR(p0_percus_yevick(phi, sigma), expected, 1e-12 * expected) << phi << " " << sigma;
    }
  }
}

// Below sigma = 0 (the probe's centre within a radius of the spheres' surfaces) P0 is
// exactly 1 - phi (1 + sigma)^3: the prediction continues it smoothly, value, slope and
// curvature, at sigma = 0.
TEST(PoresP0, PercusYevickContinuesTheExactSmallProbeForm) {
  const double phi = 0.6, h = 1e-4;
  const auto exact = [&](double sigma) { return std::log(1.0 - phi * std::pow(1 + sigma, 3)); };
  const auto py = [&](double sigma) { return std::log(p0_percus_yevick(phi, sigma)); };
  EXPECT_NEAR(py(0.0), exact(0.0), 1e-14);
  EXPECT_NEAR((py(h) - py(0)) / h, (exact(0) - exact(-h)) / h, 1e-2);
  EXPECT_NEAR((py(2 * h) - 2 * py(h) + py(0)) / (h * h),
              (exact(0) - 2 * exact(-h) + exact(-2 * h)) / (h * h), 0.5);
}

// 3 x 3 x 3 cells of touching spheres of radius 1 in a periodic box of side 3 x 2 sqrt 2.
Frame periodic_fcc() {
  const double a = 2.0 * std::sqrt(2.0);
  Frame f = box_frame(4 * 27, 3 * a);
  f.container = granpipe::Container::periodic_box(3, {0, 0, 0}, {3 * a, 3 * a, 3 * a});
  Eigen::Index k = 0;
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int l = 0; l < 3; ++l)
        for (const auto& b : basis)
          f.position().row(k++) << a * (i + b[0]), a * (j + b[1]), a * (l + b[2]);
  return f;
}

// The analyzer on a periodic fcc crystal: P0(0) = 1 - pi / (3 sqrt 2), and a probe wider
// than the octahedral hole (sigma > sqrt 2 - 1) fits nowhere.
TEST(PoresP0, AnalyzerMeasuresACrystal) {
  const auto ctx = granpipe::test::make_context(
      "pores", {{"probes", 20000}, {"sigma_step", 0.25}, {"sigma_max", 0.5}});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  granpipe::FrameCache cache;
  analyzer->consume(periodic_fcc(), cache);
  granpipe::Results results;
  analyzer->finish(results);
  const double phi = M_PI / (3.0 * std::sqrt(2.0));
  EXPECT_NEAR(results.scalar("phi").value, phi, 1e-9);
  const auto& p0 = results.tables().at("p0");
  EXPECT_NEAR(p0.column("P0")[0], 1.0 - phi, 4.0 * p0.column("P0_err")[0]);
  EXPECT_EQ(p0.column("P0")[2], 0.0);  // sigma = 0.5
  EXPECT_GT(p0.column("P0")[1], 0.0);  // sigma = 0.25 < sqrt 2 - 1
}

// Probes reaching farther than half the box were refused by the neighbour search in its own
// terms ("twice the contact range"), naming neither sigma_max nor probes.
TEST(PoresP0, ProbesReachingAcrossThePeriodAreRefusedNamingSigmaMax) {
  const auto ctx = granpipe::test::make_context("pores", {{"probes", 10}, {"sigma_max", 4.0}});
  auto analyzer = granpipe::test::installed_plugins().find("pores")->make_analyzer(*ctx);
  granpipe::FrameCache cache;
  try {
    analyzer->consume(periodic_fcc(), cache);
    FAIL() << "accepted";
  } catch (const granpipe::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "pores: frame at step 0: P0 probes look up to 5 from each point "
                 "(params.sigma_max times the mean radius, and the largest radius): expected "
                 "periodic sides of at least twice that, got 8.48528 along x; lower "
                 "params.sigma_max or set probes 0 (and it to its default)");
  }
}

}  // namespace
