#include "law_fit.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::compaction {

namespace {

struct Points {
  std::vector<double> t, y;
};

Points finite_points(const std::vector<double>& t, const std::vector<double>& y) {
  Points p;
  for (std::size_t k = 0; k < t.size() && k < y.size(); ++k) {
    if (std::isfinite(t[k]) && std::isfinite(y[k])) {
      p.t.push_back(t[k]);
      p.y.push_back(y[k]);
    }
  }
  return p;
}

// The first point, and the mean of the last tenth (at least one point) of them.
SeriesEnds series_ends(const Points& p) {
  SeriesEnds e;
  if (p.t.empty()) return e;
  e.y_first = p.y.front();
  const std::size_t n = p.t.size(), tail = std::max<std::size_t>(1, n / 10);
  for (std::size_t k = n - tail; k < n; ++k) {
    e.t_last += p.t[k] / static_cast<double>(tail);
    e.y_last += p.y[k] / static_cast<double>(tail);
  }
  return e;
}

// The fitted parameters with tau = exp(ln tau) and its error and covariances propagated
// (d tau = tau d ln tau); the points' scatter about the law is sqrt(chi^2 / dof), as they
// are unweighted.
LawFit reported(const CurveFit& fit) {
  LawFit out;
  out.status = fit.status;
  out.value.assign(fit.value.begin(), fit.value.end());
  out.error.assign(fit.error.begin(), fit.error.end());
  out.value.back() = std::exp(fit.value[fit.value.size() - 1]);
  out.error.back() = out.value.back() * fit.error[fit.error.size() - 1];
  out.covariance = fit.covariance;
  if (out.covariance.size() > 0) {
    const Eigen::Index last = out.covariance.rows() - 1;
    out.covariance.row(last) *= out.value.back();
    out.covariance.col(last) *= out.value.back();
  }
  out.scatter = fit.fitted() ? std::sqrt(fit.chi2 / fit.dof) : std::nan("");
  out.chi2 = fit.chi2;
  out.dof = fit.dof;
  return out;
}

}  // namespace

std::vector<double> law_start(const Law& law, const std::vector<double>& t,
                              const std::vector<double>& y) {
  Eigen::VectorXd p = law.start(series_ends(finite_points(t, y)));
  p[p.size() - 1] = std::exp(p[p.size() - 1]);
  return {p.begin(), p.end()};
}

LawFit fit_law(const Law& law, const std::vector<double>& t, const std::vector<double>& y) {
  const Points p = finite_points(t, y);
  return reported(fit_curve(law.model, p.t, p.y, {}, law.start(series_ends(p))));
}

LeastDetermined least_determined(const Law& law, const LawFit& fit) {
  LeastDetermined least;
  if (!fit.fitted()) return least;
  for (std::size_t q = 0; q < fit.value.size(); ++q) {
    const double ratio = fit.error[q] / std::abs(fit.value[q]);
    if (ratio > least.ratio) least = {law.names[q], fit.value[q], fit.error[q], ratio};
  }
  return least;
}

double law_value(const Law& law, const LawFit& fit, double t) {
  if (!fit.fitted()) return std::nan("");
  Eigen::VectorXd p = Eigen::Map<const Eigen::VectorXd>(fit.value.data(), fit.value.size());
  p[p.size() - 1] = std::log(p[p.size() - 1]);  // the model takes ln tau
  return law.model.value(p, t);
}

}  // namespace granpipe::compaction
