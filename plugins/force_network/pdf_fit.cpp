#include "pdf_fit.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <vector>

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

// What the minimiser sees: the histogram, the fixed values and which parameters it moves.
struct Problem {
  const ForcePdf& pdf;
  Parameters fixed;
  std::vector<int> moved;  // the parameter of each entry of the minimiser's vector

  Parameters parameters(const gsl_vector* x) const {
    Parameters p = fixed;
    for (std::size_t m = 0; m < moved.size(); ++m) p[moved[m]] = gsl_vector_get(x, m);
    return p;
  }
  // Poisson error of bin k; an empty bin counts as one, so that no weight is infinite.
  double sigma(std::size_t k) const {
    return std::sqrt(std::max(pdf.counts[k], 1.0)) /
           (static_cast<double>(pdf.samples) * pdf.width(k));
  }
};

int residuals(const gsl_vector* x, void* data, gsl_vector* r) {
  const auto& problem = *static_cast<const Problem*>(data);
  const Parameters p = problem.parameters(x);
  const ForcePdf& pdf = problem.pdf;
  for (std::size_t k = 0; k < pdf.bins(); ++k) {
    // Simpson's rule: the model's mean over the bin, which the histogram measures.
    const double mean =
        (eq13(p, pdf.edges[k]) + 4.0 * eq13(p, pdf.centre(k)) + eq13(p, pdf.edges[k + 1])) / 6.0;
    gsl_vector_set(r, k, (mean - pdf.density(k)) / problem.sigma(k));
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* x, void* data, gsl_matrix* jac) {
  const auto& problem = *static_cast<const Problem*>(data);
  const Parameters p = problem.parameters(x);
  const ForcePdf& pdf = problem.pdf;
  for (std::size_t k = 0; k < pdf.bins(); ++k) {
    const Parameters lo = eq13_gradient(p, pdf.edges[k]), mid = eq13_gradient(p, pdf.centre(k)),
                     hi = eq13_gradient(p, pdf.edges[k + 1]);
    for (std::size_t m = 0; m < problem.moved.size(); ++m) {
      const int q = problem.moved[m];
      gsl_matrix_set(jac, k, m, (lo[q] + 4.0 * mid[q] + hi[q]) / 6.0 / problem.sigma(k));
    }
  }
  return GSL_SUCCESS;
}

// GSL's default handler aborts the process on a numerical error; a fit that fails must
// instead come back as "not converged", so GSL reports by return codes in this process.
void gsl_reports_by_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

struct WorkspaceFree {
  void operator()(gsl_multifit_nlinear_workspace* w) const { gsl_multifit_nlinear_free(w); }
};
struct MatrixFree {
  void operator()(gsl_matrix* m) const { gsl_matrix_free(m); }
};

// Fills fit.value, fit.error, chi2 from a converged workspace; false when any is not finite.
bool read_solution(gsl_multifit_nlinear_workspace* w, const Problem& problem, PdfFit& fit) {
  const std::size_t p = problem.moved.size();
  const std::unique_ptr<gsl_matrix, MatrixFree> covariance(gsl_matrix_alloc(p, p));
  if (gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, covariance.get()) != GSL_SUCCESS)
    return false;
  const double norm = gsl_blas_dnrm2(gsl_multifit_nlinear_residual(w));
  fit.chi2 = norm * norm;
  const double scale = std::max(1.0, fit.chi2 / fit.dof);
  fit.value = problem.parameters(gsl_multifit_nlinear_position(w));
  fit.fitted_parameters = problem.moved;
  fit.covariance.resize(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
  for (std::size_t m = 0; m < p; ++m) {
    for (std::size_t l = 0; l < p; ++l) {
      fit.covariance(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(l)) =
          scale * gsl_matrix_get(covariance.get(), m, l);
    }
    fit.error[problem.moved[m]] =
        std::sqrt(fit.covariance(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m)));
  }
  bool finite = std::isfinite(fit.chi2);
  for (int q = 0; q < kParameters; ++q) {
    finite = finite && std::isfinite(fit.value[q]) && std::isfinite(fit.error[q]);
  }
  return finite && fit.covariance.allFinite();
}

// Below this reciprocal condition number of the Jacobian, J^T J's is below the double
// precision: the covariance, and the errors, are rounding noise. That is a parameter the
// data do not determine, such as the alpha of a bump that the minimiser moved out of the
// bins (errors of 1e8 and more, where determined fits have rcond above 0.01).
const double kMinRcond = std::sqrt(std::numeric_limits<double>::epsilon());

// Whether the converged workspace's parameters are all determined by the data.
bool determined(const gsl_multifit_nlinear_workspace* w) {
  double rcond = 0.0;
  return gsl_multifit_nlinear_rcond(&rcond, w) == GSL_SUCCESS && rcond >= kMinRcond;
}

// Runs the trust-region minimiser from `start`: Fitted when it converged to finite values
// and errors of determined parameters, which it leaves in `fit` (whose dof is set).
FitStatus minimise(Problem& problem, const Parameters& start, PdfFit& fit) {
  gsl_reports_by_return_codes();
  const std::size_t n = problem.pdf.bins(), p = problem.moved.size();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = jacobian;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &problem;
  const gsl_multifit_nlinear_parameters settings = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, WorkspaceFree> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &settings, n, p));
  std::vector<double> x;
  for (int q : problem.moved) x.push_back(start[q]);
  gsl_vector_view x0 = gsl_vector_view_array(x.data(), p);
  int info = 0;
  const bool converged = gsl_multifit_nlinear_init(&x0.vector, &fdf, w.get()) == GSL_SUCCESS &&
                         gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 0.0, nullptr, nullptr,
                                                     &info, w.get()) == GSL_SUCCESS;
  if (!converged) return FitStatus::NotConverged;
  if (!determined(w.get())) return FitStatus::NotDetermined;
  return read_solution(w.get(), problem, fit) ? FitStatus::Fitted : FitStatus::NotConverged;
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
  Problem problem{pdf, request.start, {}};
  for (int q = 0; q < kParameters; ++q) {
    if (request.free[q]) problem.moved.push_back(q);
  }
  PdfFit fit;
  const std::size_t n = pdf.bins(), p = problem.moved.size();
  if (pdf.samples < request.min_samples || n <= p || p == 0) return fit;
  fit.dof = static_cast<int>(n - p);
  fit.status = minimise(problem, request.start, fit);
  if (fit.fitted()) return fit;
  PdfFit none;  // no values from a failed minimisation
  none.status = fit.status;
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
