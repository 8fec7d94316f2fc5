#pragma once
// A law of compaction_laws.hpp fitted to a series (t, y) of one run by the core fitter.
// The points carry no errors of their own: the fit is unweighted, and the scatter s of the
// points about the law (root mean square residual over the degrees of freedom) stands for
// every point's sigma. The core scales the errors of a fit with chi^2/dof > 1 to s already;
// below 1 (y much smaller than 1, as a packing fraction's scatter) it does not, and the
// errors are scaled here, so that they are the usual least-squares ones whatever the size
// of y. Successive frames of one run are correlated: the errors are those of independent
// points.
#include <Eigen/Core>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "compaction_laws.hpp"
#include "granpipe/curve_fit.hpp"

namespace granpipe::compaction {

struct LawFit {
  CurveFitStatus status = CurveFitStatus::TooFewPoints;
  std::vector<double> value, error;  // in Law::names order, tau itself; NaN when not fitted
  Eigen::MatrixXd covariance;        // of value, tau's row and column too; empty when not fitted
  // s, the points' spread about the law, and chi^2: NaN when not fitted.
  double scatter = std::numeric_limits<double>::quiet_NaN();
  double chi2 = std::numeric_limits<double>::quiet_NaN();
  int dof = 0;
  bool fitted() const { return status == CurveFitStatus::Fitted; }
};

// The fitted law at t (for the curve drawn over the points); NaN when it was not fitted.
double law_value(const Law& law, const LawFit& fit, double t);

// Points with a non-finite t or y are left out.
LawFit fit_law(const Law& law, const std::vector<double>& t, const std::vector<double>& y);

// The parameter of a fitted law its error leaves least determined, and that error over the
// parameter's magnitude (ratio 0 and no name when not fitted): a fit can converge with
// errors hundreds of times its values (the paper: (X_inf, B, tau) is not unique at small
// epsilon), which a status of "fitted" alone does not say.
struct LeastDetermined {
  std::string name;
  double value = 0.0, error = 0.0;
  double ratio = 0.0;  // error / |value|: infinite for a value of 0 with an error
  // An error above the value: the data barely determine the law (said in the log).
  bool barely_determined() const { return ratio > 1.0; }
};
LeastDetermined least_determined(const Law& law, const LawFit& fit);

// The start values fit_law begins from (tau itself), from the ends of the finite points.
std::vector<double> law_start(const Law& law, const std::vector<double>& t,
                              const std::vector<double>& y);

}  // namespace granpipe::compaction
