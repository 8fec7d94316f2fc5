// The shared curve fitter: parameters recovered from noisy data within their errors, the
// errors themselves the right size, and fits that cannot be made reported as undefined.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "granpipe/curve_fit.hpp"

using namespace granpipe;

namespace {

// y = a exp(-x / b) + c
CurveModel decay() {
  return {[](const Eigen::VectorXd& p, double x) { return p[0] * std::exp(-x / p[1]) + p[2]; },
          [](const Eigen::VectorXd& p, double x) {
            const double e = std::exp(-x / p[1]);
            Eigen::VectorXd g(3);
            g << e, p[0] * e * x / (p[1] * p[1]), 1.0;
            return g;
          }};
}

}  // namespace

// Over many noisy samples the fitted values scatter about the truth by their errors: the
// pull (value - truth) / error has mean ~0 and spread ~1.
TEST(CurveFit, RecoversParametersWithErrorsOfTheRightSize) {
  const Eigen::Vector3d truth(2.0, 3.0, 0.5);
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.02);
  double pull_sum = 0.0, pull_square = 0.0;
  const int samples = 200;
  for (int s = 0; s < samples; ++s) {
    std::vector<double> x, y;
    for (int k = 0; k < 60; ++k) {
      x.push_back(0.25 * k);
      y.push_back(decay().value(truth, x.back()) + noise(rng));
    }
    const CurveFit fit = fit_curve(decay(), x, y, {}, Eigen::Vector3d(1.0, 1.0, 0.0));
    ASSERT_TRUE(fit.fitted()) << describe(fit.status);
    const double pull = (fit.value[1] - truth[1]) / fit.error[1];
    pull_sum += pull;
    pull_square += pull * pull;
  }
  const double mean = pull_sum / samples;
  EXPECT_NEAR(mean, 0.0, 0.25);
  EXPECT_NEAR(std::sqrt(pull_square / samples - mean * mean), 1.0, 0.2);
}

TEST(CurveFit, WeightsAreHonouredAndNonFinitePointsLeftOut) {
  const Eigen::Vector3d truth(1.0, 2.0, -1.0);
  std::vector<double> x, y, sigma;
  for (int k = 0; k < 20; ++k) {
    x.push_back(0.5 * k);
    y.push_back(decay().value(truth, x.back()));
    sigma.push_back(0.1);
  }
  x.push_back(3.0);
  y.push_back(std::nan(""));  // an undefined measurement
  sigma.push_back(0.1);
  x.push_back(4.0);
  y.push_back(100.0);  // an outlier with an infinite error: no weight
  sigma.push_back(INFINITY);
  const CurveFit fit = fit_curve(decay(), x, y, sigma, Eigen::Vector3d(0.5, 1.0, 0.0));
  ASSERT_TRUE(fit.fitted()) << describe(fit.status);
  EXPECT_EQ(fit.dof, 17);
  for (int q = 0; q < 3; ++q) EXPECT_NEAR(fit.value[q], truth[q], 1e-8);
}

TEST(CurveFit, TooFewPointsOrAnUndeterminedParameterAreUndefinedNotZero) {
  const CurveFit few =
      fit_curve(decay(), {0.0, 1.0, 2.0}, {1.0, 0.5, 0.2}, {}, Eigen::Vector3d(1.0, 1.0, 0.0));
  EXPECT_EQ(few.status, CurveFitStatus::TooFewPoints);
  EXPECT_TRUE(std::isnan(few.value[0]));
  EXPECT_TRUE(std::isnan(few.error[2]));
  // y = a b x: only the product is determined.
  const CurveModel product{[](const Eigen::VectorXd& p, double x) { return p[0] * p[1] * x; },
                           [](const Eigen::VectorXd& p, double x) {
                             Eigen::VectorXd g(2);
                             g << p[1] * x, p[0] * x;
                             return g;
                           }};
  const CurveFit undetermined =
      fit_curve(product, {1.0, 2.0, 3.0, 4.0}, {2.0, 4.0, 6.0, 8.0}, {}, Eigen::Vector2d(1.0, 1.0));
  EXPECT_EQ(undetermined.status, CurveFitStatus::NotDetermined);
  EXPECT_TRUE(std::isnan(undetermined.value[1]));
  EXPECT_EQ(describe(undetermined.status), "not fitted: a parameter is not determined by the data");
}

// Points a line goes through exactly: the scatter, hence every error, is about 0, and the fit
// is a fit (a zero variance from GSL means an undetermined parameter only before the scaling
// by the scatter).
TEST(CurveFit, DataOnTheCurveAreFittedWithErrorsZero) {
  const CurveModel line{[](const Eigen::VectorXd& p, double x) { return p[0] + p[1] * x; },
                        [](const Eigen::VectorXd&, double x) {
                          Eigen::VectorXd g(2);
                          g << 1.0, x;
                          return g;
                        }};
  const CurveFit fit =
      fit_curve(line, {0.0, 1.0, 2.0, 3.0}, {1.0, 3.0, 5.0, 7.0}, {}, Eigen::Vector2d(0.0, 0.0));
  ASSERT_TRUE(fit.fitted()) << describe(fit.status);
  EXPECT_NEAR(fit.value[0], 1.0, 1e-9);
  EXPECT_NEAR(fit.value[1], 2.0, 1e-9);
  EXPECT_LT(fit.error[0], 1e-9);
  EXPECT_LT(fit.error[1], 1e-9);
}
