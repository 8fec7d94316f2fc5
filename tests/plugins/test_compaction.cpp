// The compaction analyzer's maths on synthetic data with known answers: the laws of Eqs.
// (3), (4) and (6) fitted back from noisy samples, the power spectrum of shaped 1/f^alpha
// noise, the steady state of a known series, <Z> of a lattice, the ageing differences, and
// the analyzer on the spheres3d_tap source's own frames.
#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ageing.hpp"
#include "compaction_analyzer.hpp"
#include "compaction_laws.hpp"
#include "compaction_report.hpp"
#include "frame_measure.hpp"
#include "granpipe/container.hpp"
#include "granpipe/errors.hpp"
#include "granpipe/format_number.hpp"
#include "law_fit.hpp"
#include "plugin_harness.hpp"
#include "power_spectrum.hpp"
#include "steady_state.hpp"

using namespace granpipe;
using namespace granpipe::compaction;

namespace {

// Taps as a tapping run saves them: every 20th up to 4000, and ten per decade below.
std::vector<double> run_taps() {
  std::vector<double> t;
  for (int k = 0; k <= 4000; k += 20) t.push_back(k);
  for (int d = 0; d < 30; ++d) t.push_back(std::round(std::pow(10.0, d / 10.0)));
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

// The law at `truth` (tau itself, last) plus Gaussian noise of this sigma.
std::vector<double> noisy(const Law& law, const std::vector<double>& truth,
                          const std::vector<double>& t, double sigma, unsigned seed) {
  Eigen::VectorXd p = Eigen::Map<const Eigen::VectorXd>(truth.data(), truth.size());
  p[p.size() - 1] = std::log(p[p.size() - 1]);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  std::vector<double> y;
  for (double x : t) y.push_back(law.model.value(p, x) + noise(rng));
  return y;
}

void expect_recovered(const Law& law, const std::vector<double>& truth, double sigma) {
  const std::vector<double> t = run_taps();
  for (unsigned seed : {1u, 2u, 3u}) {
    const LawFit fit = fit_law(law, t, noisy(law, truth, t, sigma, seed));
    ASSERT_TRUE(fit.fitted()) << law.formula << ": " << describe(fit.status);
    for (std::size_t q = 0; q < truth.size(); ++q) {
      EXPECT_NEAR(fit.value[q], truth[q], 3.0 * fit.error[q])
          << law.formula << ", " << law.names[q] << ", seed " << seed;
      EXPECT_LT(fit.error[q], 0.5 * std::abs(truth[q])) << law.names[q] << " barely determined";
    }
    EXPECT_NEAR(fit.scatter, sigma, 0.2 * sigma);
    // The covariance is of the parameters reported, tau's too (the results stored none).
    ASSERT_EQ(fit.covariance.rows(), static_cast<Eigen::Index>(truth.size()));
    EXPECT_TRUE(
        fit.covariance.isApprox(fit.covariance.transpose(), 1e-12));  // tau's row and column
    for (std::size_t q = 0; q < truth.size(); ++q) {
      const auto k = static_cast<Eigen::Index>(q);
      EXPECT_NEAR(std::sqrt(fit.covariance(k, k)), fit.error[q], 1e-9 * fit.error[q]);
    }
  }
}

TEST(Compaction, Eq3FitRecoversThePackingFractionLaw) {
  expect_recovered(eq3_law(), {0.62, 0.04, 0.5, 5.0}, 5e-4);
}

TEST(Compaction, Eq4FitRecoversTheMeanHeightLaw) {
  expect_recovered(eq4_law(), {14.0, 15.0, 0.5, 3.0}, 0.01);
}

TEST(Compaction, Eq6FitRecoversTheAgeingLaw) {
  expect_recovered(eq6_law(), {0.05, 1.0, 20.0}, 5e-4);
}

// The least determined parameter is the one of the largest error over value; a value of
// 0 with an error is the least determined of all.
TEST(Compaction, TheLeastDeterminedParameterHasTheLargestRelativeError) {
  LawFit fit;
  fit.status = CurveFitStatus::Fitted;
  fit.value = {0.6, 0.02, 0.4, 5.0};
  fit.error = {0.001, 0.01, 0.3, 2.0};
  LeastDetermined least = least_determined(eq3_law(), fit);
  EXPECT_EQ(least.name, "B");
  EXPECT_DOUBLE_EQ(least.ratio, 0.75);
  EXPECT_EQ(least.value, 0.4);
  EXPECT_EQ(least.error, 0.3);
  fit.value[1] = 0.0;
  EXPECT_EQ(least_determined(eq3_law(), fit).name, "dX_inf");
  EXPECT_EQ(least_determined(eq3_law(), LawFit{}).ratio, 0.0);  // not fitted: nothing to name
}

// A compaction of 0.001 under noise of 0.001: the fit of Eq. (3) converges ("fitted") with
// tau's error 12 times its value, which only the _err scalars said. The log says it now;
// the clean Eq. (4) fit of <Z> beside it is not named.
TEST(Compaction, AFitTheDataBarelyDetermineIsSaid) {
  Series s;
  s.tap = run_taps();
  s.phi_b = s.phi_c = noisy(eq3_law(), {0.62, 0.001, 0.5, 5.0}, s.tap, 1e-3, 3);
  s.z_mean = noisy(eq4_law(), {14.0, 15.0, 0.5, 3.0}, s.tap, 0.01, 1);
  const LawFit wide = fit_law(eq3_law(), s.tap, s.phi_b);
  ASSERT_TRUE(wide.fitted()) << describe(wide.status);
  const LeastDetermined least = least_determined(eq3_law(), wide);
  ASSERT_EQ(least.name, "tau");
  ASSERT_GT(least.ratio, 10.0);
  const auto ctx = test::make_context("compaction", {});
  ctx->keep_log();
  Results results;
  report_compaction(s, ReportSettings{}, results, ctx->log());
  const std::vector<std::string> lines = ctx->logged_lines();
  for (const char* fit : {"eq3_phi_b", "eq3_phi_c"}) {
    const std::string line = std::string("warning: compaction: ") + fit +
                             ": fitted, but tau = " + granpipe::format_number(least.value) +
                             " +- " + granpipe::format_number(least.error) +
                             ", an error above its value: the data barely determine the law";
    EXPECT_EQ(std::count(lines.begin(), lines.end(), line), 1) << line;
  }
  for (const std::string& line : lines)
    EXPECT_EQ(line.find("eq4_z_mean"), std::string::npos) << line;
}

// The curve drawn through the points is the fitted law itself: on exact Eq. (3) data it
// passes through every point.
TEST(Compaction, FittedLawValueReproducesExactData) {
  const std::vector<double> t = run_taps();
  const std::vector<double> y = noisy(eq3_law(), {0.62, 0.04, 0.5, 5.0}, t, 0.0, 1);
  const LawFit fit = fit_law(eq3_law(), t, y);
  ASSERT_TRUE(fit.fitted());
  for (std::size_t k = 0; k < t.size(); ++k)
    EXPECT_NEAR(law_value(eq3_law(), fit, t[k]), y[k], 1e-9);
  LawFit unfitted = fit;
  unfitted.status = CurveFitStatus::NotConverged;
  EXPECT_TRUE(std::isnan(law_value(eq3_law(), unfitted, 10.0)));
}

// The analytic gradients against central differences, for the minimiser's sake.
TEST(Compaction, LawGradientsMatchFiniteDifferences) {
  for (const Law* law : {&eq3_law(), &eq4_law(), &eq6_law()}) {
    Eigen::VectorXd p(law->names.size());
    if (p.size() == 4)
      p << 0.7, 0.2, 0.8, std::log(3.0);
    else
      p << 0.3, 0.8, std::log(3.0);
    for (double t : {0.0, 1.0, 37.0, 2500.0}) {
      const Eigen::VectorXd g = law->model.gradient(p, t);
      for (Eigen::Index q = 0; q < p.size(); ++q) {
        Eigen::VectorXd up = p, down = p;
        up[q] += 1e-6;
        down[q] -= 1e-6;
        const double numeric = (law->model.value(up, t) - law->model.value(down, t)) / 2e-6;
        EXPECT_NEAR(g[q], numeric, 1e-6 * (1.0 + std::abs(numeric))) << law->formula << " q " << q;
      }
    }
  }
}

TEST(Compaction, StartValuesPassThroughBothEnds) {
  const std::vector<double> t{0, 10, 100, 1000}, y{0.58, 0.59, 0.60, 0.61};
  const std::vector<double> p = law_start(eq3_law(), t, y);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_DOUBLE_EQ(p[0] - p[1], 0.58);  // X(0) = X_inf - dX
  EXPECT_DOUBLE_EQ(p[3], 1.0);          // tau = 1 tap
  EXPECT_NEAR(p[0] - p[1] / (1.0 + p[2] * std::log1p(1000.0)), 0.61, 1e-12);
}

TEST(Compaction, TooFewPointsLeaveTheFitUndefined) {
  const LawFit fit = fit_law(eq3_law(), {0, 1, 2}, {0.58, 0.59, 0.60});
  EXPECT_EQ(fit.status, CurveFitStatus::TooFewPoints);
  for (double v : fit.value) EXPECT_TRUE(std::isnan(v));
  for (double e : fit.error) EXPECT_TRUE(std::isnan(e));
}

// <Z> of 40 taps at epsilon 0.05 (tap3d_ageing, 1024 spheres, replica 2): it rises, then
// falls, which Eq. (4) cannot follow. The fit ran off to tau = 1.4e20, where Z_inf, B and
// tau enter only through t/tau, and was reported fitted, with an error of exactly 0 on
// Z_inf and 1e33 on B.
TEST(Compaction, AFitThatRunsOffIsUndeterminedNotFittedWithAZeroError) {
  const std::vector<double> z{14.769551, 15.019905, 15.021672, 15.049595, 15.033167, 15.072977,
                              15.099577, 15.108332, 15.050388, 15.046157, 14.973076, 15.014822,
                              15.028316, 15.00975,  14.963616, 14.871555, 14.867611, 14.960819,
                              14.911352, 14.974088, 15.005506, 14.909977, 14.841954, 14.829851,
                              14.796863, 14.756641, 14.848437, 14.781976, 14.710194, 14.733209,
                              14.774973, 14.84142,  14.847523, 14.744955, 14.681762, 14.648375,
                              14.634517, 14.693094, 14.664514, 14.695428, 14.648993};
  std::vector<double> t(z.size());
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = static_cast<double>(k);
  const LawFit fit = fit_law(eq4_law(), t, z);
  EXPECT_EQ(fit.status, CurveFitStatus::NotDetermined) << describe(fit.status);
  for (double v : fit.value) EXPECT_TRUE(std::isnan(v));
  for (double e : fit.error) EXPECT_TRUE(std::isnan(e));
}

// n samples of noise with S(f) ~ f^-alpha: white noise shaped by f^(-alpha/2) in Fourier space.
std::vector<double> power_law_noise(double alpha, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> white(0.0, 1.0);
  std::vector<double> x(n);
  for (double& v : x) v = white(rng);
  gsl_fft_real_wavetable* rt = gsl_fft_real_wavetable_alloc(n);
  gsl_fft_halfcomplex_wavetable* ht = gsl_fft_halfcomplex_wavetable_alloc(n);
  gsl_fft_real_workspace* work = gsl_fft_real_workspace_alloc(n);
  gsl_fft_real_transform(x.data(), 1, n, rt, work);
  x[0] = 0.0;
  for (std::size_t k = 1; 2 * k <= n; ++k) {
    const double shape = std::pow(static_cast<double>(k), -alpha / 2.0);
    x[2 * k - 1] *= shape;
    if (2 * k < n) x[2 * k] *= shape;
  }
  gsl_fft_halfcomplex_inverse(x.data(), 1, n, ht, work);
  gsl_fft_real_workspace_free(work);
  gsl_fft_halfcomplex_wavetable_free(ht);
  gsl_fft_real_wavetable_free(rt);
  return x;
}

TEST(Compaction, SpectrumSlopeRecoversThePowerLawExponent) {
  for (double alpha : {1.0, 1.5}) {
    for (unsigned seed : {4u, 5u}) {
      const Slope s = log_log_slope(power_spectrum(power_law_noise(alpha, 4096, seed), 10.0));
      EXPECT_NEAR(-s.value, alpha, std::max(s.error, 0.1)) << "alpha " << alpha;
      EXPECT_GT(s.error, 0.0);
      EXPECT_LT(s.error, 0.1);
    }
  }
}

// Parseval: the one-sided spectrum integrates to the variance (population) of the series.
TEST(Compaction, SpectrumIntegratesToTheVariance) {
  for (std::size_t n : {64u, 75u}) {  // even and odd lengths
    const std::vector<double> x = power_law_noise(1.0, n, 6);
    const Spectrum s = power_spectrum(x, 5.0);
    ASSERT_EQ(s.frequency.size(), n / 2);
    EXPECT_DOUBLE_EQ(s.frequency[0], 1.0 / (5.0 * static_cast<double>(n)));
    double integral = 0.0;
    for (double p : s.power) integral += p / (5.0 * static_cast<double>(n));
    EXPECT_NEAR(integral, steady_state(x).sigma * steady_state(x).sigma, 1e-12);
  }
}

// A constant series of a prime length: the mean's sum rounds, and the transform of that
// rounding gave powers of 1e-63 and a slope of 1.67 +- 0.31 (exit 0). No power at all.
TEST(Compaction, AConstantSeriesHasNoSpectrumWhateverItsLength) {
  for (std::size_t n : {11u, 13u, 16u, 101u}) {
    const Spectrum s = power_spectrum(std::vector<double>(n, 1.1), 1.0);
    EXPECT_EQ(positive_powers(s), 0u) << n;
    EXPECT_TRUE(std::isnan(log_log_slope(s).value)) << n;
  }
  // A fluctuation of a millionth of the value is one.
  std::vector<double> x(11, 1.1);
  x[3] += 1e-6;
  EXPECT_GT(positive_powers(power_spectrum(x, 1.0)), 0u);
}

TEST(Compaction, TheSpectrumUsesTheLastUnbrokenGridOfFrames) {
  // Saved every 10 taps, the log frames 63 and 79 between, the save of tap 60 missing.
  const std::vector<double> taps{40, 50, 63, 70, 79, 80, 90, 100, 110, 120};
  const EvenFrames even = evenly_spaced(taps);
  EXPECT_EQ(even.spacing, 10.0);
  std::vector<double> used;
  for (std::size_t k : even.index) used.push_back(taps[k]);
  EXPECT_EQ(used, (std::vector<double>{70, 80, 90, 100, 110, 120}));
}

// A run of 65 taps saving every 2nd and its last: the grid was anchored at tap 65, whose
// neighbour 63 has no frame, and the spectrum had 1 frame of 33.
TEST(Compaction, ALastFrameOffTheGridLeavesTheGridBeforeIt) {
  std::vector<double> taps;
  for (int t = 0; t <= 64; t += 2) taps.push_back(t);
  taps.push_back(65);
  const EvenFrames even = evenly_spaced(taps);
  EXPECT_EQ(even.spacing, 2.0);
  ASSERT_EQ(even.index.size(), 33u);
  EXPECT_EQ(taps[even.index.front()], 0.0);
  EXPECT_EQ(taps[even.index.back()], 64.0);
}

// A NaN among the values made the mean NaN, every deviation was passed as none and the
// spectrum came out zero at every frequency, exit 0.
TEST(Compaction, AnUndefinedValueLeavesTheSpectrumUndefined) {
  std::vector<double> x{1.0, 2.0, 1.5, 0.5, 1.0, 2.5, 1.0, 0.0};
  x[3] = std::nan("");
  const Spectrum s = power_spectrum(x, 1.0);
  ASSERT_EQ(s.power.size(), 4u);
  for (double p : s.power) EXPECT_TRUE(std::isnan(p));
  EXPECT_EQ(s.frequency.back(), 0.5);
  EXPECT_TRUE(std::isnan(log_log_slope(s).value));
}

// One frame shows no fluctuation and no spacing: sigma and the spectrum's spacing were 0.
TEST(Compaction, OneFrameLeavesSigmaAndSpacingUndefined) {
  const SteadyState s = steady_state({2.0});
  EXPECT_EQ(s.mean, 2.0);
  EXPECT_TRUE(std::isnan(s.sigma));
  EXPECT_TRUE(std::isnan(evenly_spaced({5.0}).spacing));
}

TEST(Compaction, SteadyStateOfAKnownSeries) {
  const SteadyState s = steady_state({1.0, 2.0, std::nan(""), 3.0, 4.0});
  EXPECT_EQ(s.frames, 4);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.sigma, std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(s.mean_error, std::sqrt(1.25 / 3.0));
}

// A simple cubic stack of spheres of radius 1, three layers on a base at z = -2.
Frame cubic_stack(std::int64_t tap) {
  Frame f;
  f.resize(27, 3);
  f.radius().setConstant(1.0);
  for (int k = 0; k < 27; ++k)
    f.position().row(k) << 1 + 2 * (k % 3), 1 + 2 * (k / 3 % 3), -1 + 2 * (k / 9);
  f.container = Container::open_top_box(3, Eigen::Vector3d(0, 0, -2), Eigen::Vector3d(6, 6, 10));
  if (tap >= 0) f.set_observable({"tap", Scope::Frame, ValueType::Integer, 1, "", "tap"}, tap);
  return f;
}

// The analyzer's results over `frames`, and the lines it logged.
struct Analysis {
  Results results;
  std::vector<std::string> log;
};
Analysis analyze_logged(const std::vector<Frame>& frames, nlohmann::json params = {}) {
  const auto ctx = test::make_context("compaction", std::move(params));
  ctx->keep_log();
  CompactionAnalyzer analyzer(*ctx);
  FrameCache cache;
  for (const Frame& f : frames) analyzer.consume(f, cache);
  Analysis a;
  analyzer.finish(a.results);
  a.log = ctx->logged_lines();
  return a;
}

Results analyze(const std::vector<Frame>& frames, nlohmann::json params = {}) {
  return analyze_logged(frames, std::move(params)).results;
}

std::vector<Frame> cubic_stacks(const std::vector<int>& taps) {
  std::vector<Frame> frames;
  for (int tap : taps) frames.push_back(cubic_stack(tap));
  return frames;
}

// A bed that never moves: every power is 0 and the slopes were NaN without a word.
TEST(Compaction, ASpectrumWithoutFluctuationsSaysWhyItsSlopeIsUndefined) {
  std::vector<Frame> frames;
  for (int tap = 0; tap < 20; ++tap) frames.push_back(cubic_stack(tap));
  const Analysis a = analyze_logged(frames);
  EXPECT_TRUE(std::isnan(a.results.scalar("spectrum_slope_z_mean").value));
  // (The laws' fits to a bed that never moves are said undefined before.)
  std::vector<std::string> spectra;
  for (const std::string& line : a.log)
    if (line.find("power spectrum") != std::string::npos) spectra.push_back(line);
  granpipe::test::expect_said_once(spectra,
                                   "warning: compaction: the power spectrum of z_mean is zero at "
                                   "all but 0 frequencies (it hardly fluctuates); its slope is "
                                   "left undefined",
                                   "spectrum of z_mean");
}

TEST(Compaction, MeanHeightOfALatticeIsInMeanRadiiAboveTheBottom) {
  // Centres at 1, 3 and 5 radii above the base.
  EXPECT_DOUBLE_EQ(mean_height_in_radii(cubic_stack(0)), 3.0);
  Frame raised = cubic_stack(0);
  raised.container.wall_offset.z() = 0.5;  // a driven base half a radius up
  EXPECT_DOUBLE_EQ(mean_height_in_radii(raised), 2.5);
  // The lowest layer's cut fraction is pi/6 (simple cubic) over its two radii, and so is
  // phi_b over four radii: two whole layers.
  const FramePoint p = measure_frame(cubic_stack(7), StereologySettings{}, "test");
  EXPECT_EQ(p.tap, 7.0);
  EXPECT_NEAR(p.phi_b, M_PI / 6.0, 1e-9);
}

// A t_w below 0 was accepted and left out with a warning as if it were a tap not saved.
TEST(Compaction, ANegativeWaitingTimeIsRefused) {
  EXPECT_EQ(
      granpipe::test::input_error_of([] {
        granpipe::test::make_context(granpipe::compaction::schema(), {{"waiting_times", {10, -1}}});
      }),
      "test: params.waiting_times: expected a list of at most 1000 integers >= 0, got [10,-1]");
}

// A list of 1e6 was taken: a warning per missing tap, 70 MB of run.log, past a SIGTERM.
TEST(Compaction, MoreThanAThousandWaitingTimesAreRefused) {
  std::vector<std::int64_t> many(1001);
  for (std::size_t k = 0; k < many.size(); ++k) many[k] = static_cast<std::int64_t>(k);
  const std::string m = granpipe::test::input_error_of([&] {
    granpipe::test::make_context(granpipe::compaction::schema(), {{"waiting_times", many}});
  });
  EXPECT_EQ(m.substr(0, m.find(", got")),
            "test: params.waiting_times: expected a list of at most 1000 integers >= 0");
  many.pop_back();
  EXPECT_NO_THROW(
      granpipe::test::make_context(granpipe::compaction::schema(), {{"waiting_times", many}}));
}

// A t_w given twice entered the ageing table and its fit twice.
TEST(Compaction, ARepeatedWaitingTimeIsRefused) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              const auto ctx = test::make_context("compaction", {{"waiting_times", {1, 10, 1}}});
              CompactionAnalyzer analyzer(*ctx);
            }),
            "params.waiting_times: expected distinct waiting times, got 1 more than once");
}

TEST(Compaction, AFrameWithoutATapIsRefused) {
  EXPECT_EQ(granpipe::test::input_error_of([] {
              measure_frame(cubic_stack(-1), StereologySettings{}, "compaction: frame 3 (step 0)");
            }),
            "compaction: frame 3 (step 0): expected the observable \"tap\" (frames of a "
            "tapping source such as spheres3d_tap), got a frame without it");
}

// A tap below 0 went into the fits' time axis, and a tap stored as a real number was
// called a frame without it.
TEST(Compaction, ATapBelowZeroOrNotAnIntegerIsRefused) {
  Frame negative = cubic_stack(-1);
  negative.set_observable({"tap", Scope::Frame, ValueType::Integer, 1, "", "tap"},
                          std::int64_t{-4});
  EXPECT_EQ(granpipe::test::input_error_of(
                [&] { measure_frame(negative, StereologySettings{}, "compaction: frame 3"); }),
            "compaction: frame 3: expected the observable \"tap\" (frames of a tapping source "
            "such as spheres3d_tap), got tap -4 (below 0)");
  Frame real = cubic_stack(-1);
  real.set_observable({"tap", Scope::Frame, ValueType::Real, 1, "", "tap"}, 4.0);
  EXPECT_EQ(granpipe::test::input_error_of(
                [&] { measure_frame(real, StereologySettings{}, "compaction: frame 3"); }),
            "compaction: frame 3: expected the observable \"tap\" (frames of a tapping source "
            "such as spheres3d_tap), got one of type real with 1 component(s) (a tap is one "
            "integer)");
}

TEST(Compaction, TapsGoingBackAreRefused) {
  EXPECT_THROW(analyze({cubic_stack(5), cubic_stack(5)}), InputError);
}

TEST(Compaction, AgeingSquaresTheChangeSinceEachWaitingTime) {
  const Ageing a = ageing({0, 1, 2, 4}, {10.0, 9.0, 8.5, 8.0}, {1, 3});
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[0].t_w, 1.0);
  EXPECT_EQ(a.points[0].t, 1.0);
  EXPECT_DOUBLE_EQ(a.points[0].squared_difference, 0.25);
  EXPECT_EQ(a.points[1].t, 3.0);
  EXPECT_DOUBLE_EQ(a.points[1].squared_difference, 1.0);
  EXPECT_EQ(a.left_out, (std::vector<std::int64_t>{3}));
}

TEST(Compaction, AShortRunReportsUndefinedFitsNotZeros) {
  const Results r = analyze(cubic_stacks({0, 1, 2}));
  EXPECT_EQ(r.tables().at("per_frame").rows(), 3u);
  EXPECT_EQ(r.scalar("eq3_phi_b_status").value, 1.0);  // too few points
  for (double v : r.fits().at("eq3_phi_b").values) EXPECT_TRUE(std::isnan(v));
  EXPECT_TRUE(std::isnan(r.fits().at("eq3_phi_b").chi2));  // 0 read as a perfect fit
  const Table& curves = r.tables().at("fitted_laws");
  ASSERT_EQ(curves.rows(), 3u);
  for (double v : curves.column("phi_b_eq3")) EXPECT_TRUE(std::isnan(v));  // drawn as nothing
  EXPECT_DOUBLE_EQ(curves.column("z_mean")[2], 3.0);
  EXPECT_TRUE(std::isnan(r.scalar("spectrum_slope_z_mean").value));
  EXPECT_DOUBLE_EQ(r.scalar("z_mean_ss").value, 3.0);
  EXPECT_DOUBLE_EQ(r.scalar("z_mean_sigma").value, 0.0);
}

// fit_to past the last tap was reported as the fits' end (1000 for a run of 20 taps, exit 0).
TEST(Compaction, ARangePastTheLastTapEndsThereAndSaysSo) {
  const auto [r, log] = analyze_logged(
      cubic_stacks({0, 1, 2, 3}), {{"fit_from", 1.0}, {"fit_to", 1000.0}, {"steady_from", 50.0}});
  EXPECT_EQ(r.scalar("fit_to").value, 3.0);
  EXPECT_EQ(r.tables().at("fitted_laws").rows(), 3u);
  EXPECT_TRUE(std::isnan(r.scalar("z_mean_ss").value));
  ASSERT_GE(log.size(), 5u);
  EXPECT_EQ(
      log[0],
      "warning: compaction: fit_to: 1000 taps is past the last frame's tap, 3; it ends there");
  // Three taps for three parameters: each law's fit is said undefined (only its _status
  // scalar said so before).
  EXPECT_EQ(log[1],
            "warning: compaction: eq4_z_mean: not fitted: no more points than parameters; its "
            "parameters are left undefined");
  EXPECT_EQ(log[4],
            "warning: compaction: steady_from: 50 taps is past the last frame's tap, 3; the steady "
            "state and its spectrum are undefined (NaN)");
}

// A fit range that ends before it starts, and a waiting time with no frame after it, gave
// NaN fits without a word.
TEST(Compaction, AnEmptyFitRangeAndALastWaitingTimeAreSaid) {
  const std::vector<std::string> log =
      analyze_logged(cubic_stacks({0, 1, 2, 3}), {{"fit_from", 50.0}, {"waiting_times", {1, 3}}})
          .log;
  const auto said = [&](const std::string& line) {
    return std::find(log.begin(), log.end(), line) != log.end();
  };
  EXPECT_TRUE(
      said("warning: compaction: fit_from: 50 taps is past the fits' last tap, 3: no "
           "frame to fit; Eqs. (3) and (4) are left undefined"));
  EXPECT_TRUE(
      said("warning: compaction: waiting_times: 3 is the last frame's tap, with no frame "
           "after it; left out"));
  EXPECT_TRUE(
      said("warning: compaction: Eq. (6) not fitted at t_w = 1 (ageing_fits' status); its "
           "parameters there are left undefined"));
}

// phi_b undefined in every other frame (bulk_top above the two-layer stacks): its spectrum
// was zero at every frequency with "it hardly fluctuates", and steady_frames said 10 where
// phi_b_ss was of 5, without a word.
TEST(Compaction, FramesWithoutAValueAreSaidInTheSteadyStateAndSpectrum) {
  std::vector<Frame> frames;
  for (int tap = 0; tap < 20; ++tap) {
    const Frame stack = cubic_stack(tap);
    if (tap % 2 == 0) {
      frames.push_back(stack);
      continue;
    }
    Frame f;  // the top layer taken off
    f.resize(18, 3);
    f.radius().setConstant(1.0);
    f.position() = stack.position().topRows(18);
    f.container = stack.container;
    f.set_observable({"tap", Scope::Frame, ValueType::Integer, 1, "", "tap"}, std::int64_t{tap});
    frames.push_back(f);
  }
  const Analysis a = analyze_logged(frames, {{"bulk_top", 5.0}});
  EXPECT_EQ(a.results.scalar("steady_frames").value, 10.0);
  // Two whole layers and the halves of the third below 5 R: the simple cubic pi / 6.
  EXPECT_NEAR(a.results.scalar("phi_b_ss").value, M_PI / 6.0, 1e-12);
  EXPECT_TRUE(std::isnan(a.results.scalar("spectrum_slope_phi_b").value));
  for (double p : a.results.tables().at("spectrum").column("phi_b")) EXPECT_TRUE(std::isnan(p));
  const auto said = [&](const std::string& line) {
    return std::count(a.log.begin(), a.log.end(), line);
  };
  EXPECT_EQ(said("warning: compaction: phi_b is undefined in 5 of the 10 steady-state frames: "
                 "phi_b_ss and phi_b_sigma are of the 5 with a value"),
            1);
  EXPECT_EQ(said("warning: compaction: the power spectrum of phi_b and its slope are undefined "
                 "(NaN): phi_b is undefined in 5 of the 10 evenly spaced frames"),
            1);
}

// A ramp's frames (epsilon 0.01, then 0.0225) made one "steady state" and spectrum, exit 0.
TEST(Compaction, FramesOfAnotherEpsilonAreRefused) {
  const Property epsilon{"epsilon", Scope::Frame, ValueType::Real, 1, "", "dilation"};
  std::vector<Frame> frames = cubic_stacks({0, 1, 2, 3});
  for (std::size_t k = 0; k < frames.size(); ++k)
    frames[k].set_observable(epsilon, k == 0 ? 0.0 : k < 3 ? 0.01 : 0.0225);
  const auto ctx = test::make_context("compaction", {});
  CompactionAnalyzer analyzer(*ctx);
  FrameCache cache;
  for (std::size_t k = 0; k < 3; ++k) analyzer.consume(frames[k], cache);
  EXPECT_EQ(granpipe::test::input_error_of([&] { analyzer.consume(frames[3], cache); }),
            "compaction: frame 3 (step 0): expected the epsilon of frame 1 (tap 1), 0.01, got "
            "0.0225 (compaction measures a run at one epsilon; a ramp's steps: stereology's "
            "by_leg table)");
}

// A few taps of the 3D source: <Z> is its own mean_height observable in radii.
TEST(Compaction, OnTheTappingSourceMeanHeightIsTheSourcesObservable) {
  const auto ctx = test::make_context("spheres3d_tap", {{"N", 64},
                                                        {"side", 6},
                                                        {"radius", 0.5},
                                                        {"taps", 24},
                                                        {"save_every", 1},
                                                        {"epsilon", 0.1},
                                                        {"log_frames", false}});
  auto source = test::installed_plugins().find("spheres3d_tap")->make_source(*ctx);
  std::vector<Frame> frames;
  Frame f;
  while (source->next(f)) {
    const double bottom = f.container.lo.z();
    EXPECT_NEAR(mean_height_in_radii(f) * 0.5 + bottom, *f.real_observable("mean_height"), 1e-12);
    frames.push_back(f);
  }
  ASSERT_EQ(frames.size(), 25u);
  const Results r = analyze(frames, {{"waiting_times", {0, 5}}, {"steady_from", 8}});
  EXPECT_EQ(r.tables().at("per_frame").rows(), 25u);
  EXPECT_EQ(r.tables().at("spectrum").rows(), 8u);  // taps 8 to 24
  EXPECT_EQ(r.tables().at("ageing").rows(), 24u + 19u);
  EXPECT_EQ(r.tables().at("ageing_fits").rows(), 2u);
  const double phi_b = r.scalar("phi_b_ss").value;
  EXPECT_GT(phi_b, 0.4);
  EXPECT_LT(phi_b, 0.75);
}

}  // namespace

// bulk_top above the bed, perturbed_top above phi_c's zone: phi_b was the fraction of a
// slab half empty (exit 0, no word) and phi_c NaN without a word. Both are NaN now, and
// the first such frame says why.
TEST(Compaction, UndefinedFractionsAreNaNAndSaidOnce) {
  const auto [r, log] =
      analyze_logged(cubic_stacks({0, 1}), {{"bulk_top", 100.0}, {"perturbed_top", 50.0}});
  const Table& t = r.tables().at("per_frame");
  for (double v : t.column("phi_b")) EXPECT_TRUE(std::isnan(v));
  for (double v : t.column("phi_c")) EXPECT_TRUE(std::isnan(v));
  granpipe::test::expect_said_once(
      log,
      "warning: compaction: frame 0 (step 0): phi_b is undefined (NaN): bulk_top, 100 R, "
      "reaches above the highest particle top, 6 R; phi_c is undefined (NaN): its zone's "
      "top height_c, 5 R, is not above perturbed_top, 50 R; said for the first such frame "
      "only",
      "undefined (NaN)");
}
