#pragma once
// Weighted non-linear least squares of a model y(x; p) to points (x, y, sigma), by GSL's
// trust-region minimiser: the fits of the tapping papers' equations (a density profile,
// a compaction law, an ageing function). The standard errors come from the covariance:
// of unweighted points scaled by chi^2/dof (the scatter is the points' error); of weighted
// points scaled by chi^2/dof only when that exceeds 1 (the sigmas understate the scatter).
#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "granpipe/results.hpp"

namespace granpipe {

// The model's value at x for parameters p, and its gradient with respect to p.
struct CurveModel {
  std::function<double(const Eigen::VectorXd& p, double x)> value;
  std::function<Eigen::VectorXd(const Eigen::VectorXd& p, double x)> gradient;
};

enum class CurveFitStatus : std::uint8_t {
  Fitted,
  TooFewPoints,   // no more points than parameters
  NotConverged,   // or a non-finite result
  NotDetermined,  // converged, but a parameter is not determined (singular Jacobian)
};
std::string describe(CurveFitStatus s);
// The codes of a fit's status scalar, for its doc: " (status 0 fitted, 1 ...)".
inline constexpr const char* kCurveFitStatusCodes =
    " (status 0 fitted, 1 no more points than parameters, 2 no convergence, 3 a parameter "
    "not determined)";

struct CurveFit {
  CurveFitStatus status = CurveFitStatus::TooFewPoints;
  Eigen::VectorXd value, error;  // NaN when not fitted: undefined, not zero
  Eigen::MatrixXd covariance;    // scaled as the errors are; empty when not fitted
  // NaN when not fitted: a failed fit's chi^2 of 0 read as a perfect one (the report: "chi^2
  // = 0, 37 degrees of freedom").
  double chi2 = std::numeric_limits<double>::quiet_NaN();
  int dof = 0;
  bool fitted() const { return status == CurveFitStatus::Fitted; }
};

// Fits from `start`. `sigma` empty: every point weighs 1. Points whose x, y or sigma is
// not finite are left out.
CurveFit fit_curve(const CurveModel& model, const std::vector<double>& x,
                   const std::vector<double>& y, const std::vector<double>& sigma,
                   const Eigen::VectorXd& start);

// The fit as a result (Results::add_fit) of the formula `model` with these parameter
// names; values and errors NaN, chi2 NaN when it was not fitted.
Fit result_fit(const CurveFit& fit, std::string model, std::vector<std::string> names);

}  // namespace granpipe
