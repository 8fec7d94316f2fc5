#include "granpipe/curve_fit.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

namespace granpipe {
namespace {

struct Points {
  const CurveModel& model;
  bool weighted = false;
  std::vector<double> x, y, sigma;
};

Eigen::VectorXd parameters(const gsl_vector* v) {
  Eigen::VectorXd p(static_cast<Eigen::Index>(v->size));
  for (std::size_t m = 0; m < v->size; ++m) p[static_cast<Eigen::Index>(m)] = gsl_vector_get(v, m);
  return p;
}

int residuals(const gsl_vector* v, void* data, gsl_vector* r) {
  const auto& pts = *static_cast<const Points*>(data);
  const Eigen::VectorXd p = parameters(v);
  for (std::size_t k = 0; k < pts.x.size(); ++k) {
    gsl_vector_set(r, k, (pts.model.value(p, pts.x[k]) - pts.y[k]) / pts.sigma[k]);
  }
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* v, void* data, gsl_matrix* jac) {
  const auto& pts = *static_cast<const Points*>(data);
  const Eigen::VectorXd p = parameters(v);
  for (std::size_t k = 0; k < pts.x.size(); ++k) {
    const Eigen::VectorXd g = pts.model.gradient(p, pts.x[k]);
    for (Eigen::Index m = 0; m < g.size(); ++m) {
      gsl_matrix_set(jac, k, static_cast<std::size_t>(m), g[m] / pts.sigma[k]);
    }
  }
  return GSL_SUCCESS;
}

// GSL's default handler aborts the process on a numerical error; a fit that fails must
// come back as "not converged" instead.
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

// Below this reciprocal condition number of the Jacobian, J^T J's is below double
// precision: the covariance is rounding noise, a parameter is not determined.
const double kMinRcond = std::sqrt(std::numeric_limits<double>::epsilon());

// The Jacobian's reciprocal condition number with each column scaled to unit length, so
// that parameters of very different sizes do not count as ill-determined. GSL's own rcond
// passed a fit of Eq. (4) run off to tau = 10^20, where three parameters only enter
// through t/tau: their columns are collinear however small, and the covariance GSL
// returned was garbage (an error of exactly 0 on one, 10^52 on another).
double scaled_rcond(const gsl_matrix* jac) {
  Eigen::MatrixXd j(static_cast<Eigen::Index>(jac->size1), static_cast<Eigen::Index>(jac->size2));
  for (Eigen::Index k = 0; k < j.rows(); ++k)
    for (Eigen::Index m = 0; m < j.cols(); ++m)
      j(k, m) = gsl_matrix_get(jac, static_cast<std::size_t>(k), static_cast<std::size_t>(m));
  for (Eigen::Index m = 0; m < j.cols(); ++m) {
    const double norm = j.col(m).norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) return 0.0;
    j.col(m) /= norm;
  }
  const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(j).singularValues();
  return s[s.size() - 1] / s[0];
}

CurveFitStatus read_solution(gsl_multifit_nlinear_workspace* w, bool weighted, CurveFit& fit) {
  double rcond = 0.0;
  if (gsl_multifit_nlinear_rcond(&rcond, w) != GSL_SUCCESS || rcond < kMinRcond ||
      scaled_rcond(gsl_multifit_nlinear_jac(w)) < kMinRcond)
    return CurveFitStatus::NotDetermined;
  const std::size_t p = gsl_multifit_nlinear_position(w)->size;
  const std::unique_ptr<gsl_matrix, MatrixFree> covariance(gsl_matrix_alloc(p, p));
  if (gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, covariance.get()) != GSL_SUCCESS)
    return CurveFitStatus::NotConverged;
  // GSL zeroes the rows of the columns it finds dependent. (Scaled, a variance is 0 for data
  // the curve goes through exactly: errors 0 are right there.)
  for (std::size_t m = 0; m < p; ++m)
    if (!(gsl_matrix_get(covariance.get(), m, m) > 0.0)) return CurveFitStatus::NotDetermined;
  const double norm = gsl_blas_dnrm2(gsl_multifit_nlinear_residual(w));
  fit.chi2 = norm * norm;
  // Unweighted points: the scatter about the fit is their error (chi^2/dof estimates the
  // variance). Weighted: the sigmas are trusted, unless the scatter shows them too small.
  const double scale = weighted ? std::max(1.0, fit.chi2 / fit.dof) : fit.chi2 / fit.dof;
  fit.value = parameters(gsl_multifit_nlinear_position(w));
  const auto n = static_cast<Eigen::Index>(p);
  fit.covariance.resize(n, n);
  for (Eigen::Index m = 0; m < n; ++m)
    for (Eigen::Index l = 0; l < n; ++l)
      fit.covariance(m, l) = scale * gsl_matrix_get(covariance.get(), static_cast<std::size_t>(m),
                                                    static_cast<std::size_t>(l));
  fit.error = fit.covariance.diagonal().cwiseSqrt();
  const bool finite = std::isfinite(fit.chi2) && fit.value.allFinite() && fit.error.allFinite();
  return finite ? CurveFitStatus::Fitted : CurveFitStatus::NotConverged;
}

}  // namespace

std::string describe(CurveFitStatus s) {
  switch (s) {
    case CurveFitStatus::Fitted:
      return "fitted";
    case CurveFitStatus::TooFewPoints:
      return "not fitted: no more points than parameters";
    case CurveFitStatus::NotConverged:
      return "not fitted: no convergence";
    case CurveFitStatus::NotDetermined:
      return "not fitted: a parameter is not determined by the data";
  }
  return "";
}

CurveFit fit_curve(const CurveModel& model, const std::vector<double>& x,
                   const std::vector<double>& y, const std::vector<double>& sigma,
                   const Eigen::VectorXd& start) {
  gsl_reports_by_return_codes();
  Points pts{model, !sigma.empty(), {}, {}, {}};
  for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) {
    const double s = sigma.empty() ? 1.0 : sigma[k];
    if (std::isfinite(x[k]) && std::isfinite(y[k]) && std::isfinite(s) && s > 0.0) {
      pts.x.push_back(x[k]);
      pts.y.push_back(y[k]);
      pts.sigma.push_back(s);
    }
  }
  const std::size_t n = pts.x.size(), p = static_cast<std::size_t>(start.size());
  CurveFit fit;
  fit.value = fit.error = Eigen::VectorXd::Constant(start.size(), std::nan(""));
  if (n <= p || p == 0) return fit;
  fit.dof = static_cast<int>(n - p);
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = jacobian;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &pts;
  const gsl_multifit_nlinear_parameters settings = gsl_multifit_nlinear_default_parameters();
  const std::unique_ptr<gsl_multifit_nlinear_workspace, WorkspaceFree> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &settings, n, p));
  Eigen::VectorXd x0 = start;
  gsl_vector_view v0 = gsl_vector_view_array(x0.data(), p);
  int info = 0;
  const bool converged = gsl_multifit_nlinear_init(&v0.vector, &fdf, w.get()) == GSL_SUCCESS &&
                         gsl_multifit_nlinear_driver(500, 1e-10, 1e-10, 0.0, nullptr, nullptr,
                                                     &info, w.get()) == GSL_SUCCESS;
  CurveFit solved = fit;
  solved.status =
      converged ? read_solution(w.get(), pts.weighted, solved) : CurveFitStatus::NotConverged;
  if (solved.fitted()) return solved;
  fit.status = solved.status;
  return fit;
}

Fit result_fit(const CurveFit& fit, std::string model, std::vector<std::string> names) {
  Fit out;
  out.model = std::move(model);
  out.names = std::move(names);
  out.values.assign(fit.value.begin(), fit.value.end());
  out.errors.assign(fit.error.begin(), fit.error.end());
  out.covariance = fit.covariance;
  out.chi2 = fit.fitted() ? fit.chi2 : std::nan("");
  out.dof = fit.dof;
  return out;
}

}  // namespace granpipe
