#include "pdf_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "granpipe/curve_fit.hpp"

namespace granpipe::force_network {

namespace {

// The derivatives of Eq. (13) with respect to a, b, alpha, beta, gamma at f.
Parameters eq13_gradient(const Parameters& p, double f) {
  const double u = f - p[kAlpha];
  const double bump = std::exp(-u * u);
  const double decay = std::exp(-p[kBeta] * (f - p[kGamma]));
  const double value = p[kA] * (1.0 - p[kB] * bump) * decay;
  return {(1.0 - p[kB] * bump) * decay, -p[kA] * bump * decay,
          -2.0 * p[kA] * p[kB] * u * bump * decay, -(f - p[kGamma]) * value, p[kBeta] * value};
}

// What the fitter sees: x is a bin's index and the model's value there its mean over the
// bin (Simpson's rule), which the histogram measures; only the free parameters move.
struct BinMeanModel {
  const ForcePdf& pdf;
  Parameters fixed;
  std::vector<int> moved;  // the parameter of each entry of the fitter's vector

  Parameters parameters(const Eigen::VectorXd& x) const {
    Parameters p = fixed;
    for (std::size_t m = 0; m < moved.size(); ++m) p[moved[m]] = x[static_cast<Eigen::Index>(m)];
    return p;
  }
  template <class F>
  auto simpson(double x, F&& f) const {
    const auto k = static_cast<std::size_t>(x);
    return (f(pdf.edges[k]) + 4.0 * f(pdf.centre(k)) + f(pdf.edges[k + 1])) / 6.0;
  }
  CurveModel model() const {
    return {[this](const Eigen::VectorXd& x, double bin) {
              const Parameters p = parameters(x);
              return simpson(bin, [&](double f) { return eq13(p, f); });
            },
            [this](const Eigen::VectorXd& x, double bin) {
              const Parameters p = parameters(x);
              Eigen::VectorXd g(static_cast<Eigen::Index>(moved.size()));
              for (std::size_t m = 0; m < moved.size(); ++m) {
                g[static_cast<Eigen::Index>(m)] =
                    simpson(bin, [&](double f) { return eq13_gradient(p, f)[moved[m]]; });
              }
              return g;
            }};
  }
};

FitStatus status_of(CurveFitStatus s) {
  switch (s) {
    case CurveFitStatus::Fitted:
      return FitStatus::Fitted;
    case CurveFitStatus::TooFewPoints:
      return FitStatus::TooFewSamples;
    case CurveFitStatus::NotConverged:
      return FitStatus::NotConverged;
    case CurveFitStatus::NotDetermined:
      return FitStatus::NotDetermined;
  }
  return FitStatus::NotConverged;
}

// The fitter's result in the PDF's parameters: fixed ones at their values, error 0.
PdfFit pdf_fit_of(const CurveFit& c, const BinMeanModel& m) {
  PdfFit fit;
  fit.status = status_of(c.status);
  if (!fit.fitted()) return fit;
  fit.value = m.parameters(c.value);
  fit.error.fill(0.0);
  for (std::size_t q = 0; q < m.moved.size(); ++q)
    fit.error[m.moved[q]] = c.error[static_cast<Eigen::Index>(q)];
  fit.fitted_parameters = m.moved;
  fit.covariance = c.covariance;
  fit.chi2 = c.chi2;
  fit.dof = c.dof;
  return fit;
}

}  // namespace

double eq13(const Parameters& p, double f) {
  const double u = f - p[kAlpha];
  return p[kA] * (1.0 - p[kB] * std::exp(-u * u)) * std::exp(-p[kBeta] * (f - p[kGamma]));
}

const char* describe(FitStatus s) {
  switch (s) {
    case FitStatus::Fitted:
      return "fitted";
    case FitStatus::TooFewSamples:
      return "not fitted: too few samples";
    case FitStatus::NotConverged:
      return "not fitted: no convergence";
    case FitStatus::NoReference:
      return "not fitted: the full network's fit has no values";
    case FitStatus::NotDetermined:
      return "not fitted: a parameter is not determined by the data";
  }
  return "";
}

PdfFit fit_pdf(const ForcePdf& pdf, const FitRequest& request) {
  BinMeanModel model{pdf, request.start, {}};
  for (int q = 0; q < kParameters; ++q) {
    if (request.free[q]) model.moved.push_back(q);
  }
  const std::size_t n = pdf.bins(), p = model.moved.size();
  if (pdf.samples < request.min_samples || n <= p || p == 0) return {};
  std::vector<double> bins, density, sigma;
  for (std::size_t k = 0; k < n; ++k) {
    bins.push_back(static_cast<double>(k));
    density.push_back(pdf.density(k));
    // Poisson error; an empty bin counts as one, so that no weight is infinite.
    sigma.push_back(std::sqrt(std::max(pdf.counts[k], 1.0)) /
                    (static_cast<double>(pdf.samples) * pdf.width(k)));
  }
  Eigen::VectorXd start(static_cast<Eigen::Index>(p));
  for (std::size_t m = 0; m < p; ++m)
    start[static_cast<Eigen::Index>(m)] = request.start[model.moved[m]];
  const CurveFit c = fit_curve(model.model(), bins, density, sigma, start);
  if (c.fitted()) return pdf_fit_of(c, model);
  PdfFit none;  // no values from a failed minimisation
  none.status = status_of(c.status);
  return none;
}

FitRequest eq11_request(long min_samples) {
  FitRequest r;
  const double b = 0.75, beta = 1.5;
  // The integral of exp(-f^2 - beta f) over f > 0.
  const double bump =
      0.5 * std::sqrt(std::numbers::pi) * std::exp(0.25 * beta * beta) * std::erfc(0.5 * beta);
  r.start = {1.0 / (1.0 / beta - b * bump), b, 0.0, beta, 0.0};
  r.free = {true, true, false, true, false};
  r.min_samples = min_samples;
  return r;
}

}  // namespace granpipe::force_network
