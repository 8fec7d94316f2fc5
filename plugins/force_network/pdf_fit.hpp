#pragma once
// Fits of the force PDF by Eq. (13) of the paper,
//   P(f) = a (1 - b exp(-(f - alpha)^2)) exp(-beta (f - gamma)),
// of which Eq. (11) is the case alpha = gamma = 0. Any parameter may be held fixed.
//
// Weighted non-linear least squares (the core's curve fitter: GSL's trust region with
// Levenberg–Marquardt steps): the model's mean over each bin (Simpson's rule) against the
// bin's density, each bin weighted by its Poisson error (an empty bin by the error of one
// count). The standard errors come from the covariance of the fit, scaled by chi^2/dof
// when that exceeds 1 (a model that does not describe the data gets wider errors, never
// narrower ones).
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "force_pdf.hpp"

namespace granpipe::force_network {

enum Parameter : std::uint8_t { kA, kB, kAlpha, kBeta, kGamma, kParameters };
using Parameters = std::array<double, kParameters>;
inline const std::array<std::string, kParameters> kParameterNames{"a", "b", "alpha", "beta",
                                                                  "gamma"};

double eq13(const Parameters& p, double f);

// Why a fit has no values: 0 fitted; 1 too few samples or bins; 2 the minimiser did not
// converge or gave a non-finite result; 3 the fit it depends on (the full network's) has
// no values; 4 it converged, but the data do not determine every free parameter (the
// Jacobian is singular to double precision: such a parameter's error would be 1e8 or more).
enum class FitStatus : std::uint8_t {
  Fitted = 0,
  TooFewSamples = 1,
  NotConverged = 2,
  NoReference = 3,
  NotDetermined = 4
};
const char* describe(FitStatus s);

struct FitRequest {
  Parameters start{};  // start values, and the values of fixed parameters
  std::array<bool, kParameters> free{};
  long min_samples = 100;  // fewer samples: not fitted
};

// NaN in every parameter: a fit that was not made has no values, never 0.
inline Parameters undefined_parameters() {
  Parameters p;
  p.fill(std::numeric_limits<double>::quiet_NaN());
  return p;
}

struct PdfFit {
  FitStatus status = FitStatus::TooFewSamples;
  Parameters value = undefined_parameters();  // NaN when not fitted
  Parameters error = undefined_parameters();  // 0 for fixed parameters; NaN when not fitted
  std::vector<int> fitted_parameters;         // the free ones, in Parameter order
  Eigen::MatrixXd covariance;                 // of the free ones, scaled as the errors are
  double chi2 = 0.0;
  int dof = 0;
  bool fitted() const { return status == FitStatus::Fitted; }
};

PdfFit fit_pdf(const ForcePdf& pdf, const FitRequest& request);

// Eq. (11) with a, b, beta free, from b = 0.75, beta = 1.5 (Mueth et al.'s values) and the
// a that normalises it.
FitRequest eq11_request(long min_samples);

}  // namespace granpipe::force_network
