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

double scatter(const Law& law, const CurveFit& fit, const Points& p) {
  double sum = 0.0;
  for (std::size_t k = 0; k < p.t.size(); ++k) {
    const double r = law.model.value(fit.value, p.t[k]) - p.y[k];
    sum += r * r;
  }
  return std::sqrt(sum / fit.dof);
}

// The fitted parameters with tau = exp(ln tau) and its error propagated.
LawFit reported(const CurveFit& fit, double s) {
  LawFit out;
  out.status = fit.status;
  out.value.assign(fit.value.begin(), fit.value.end());
  out.error.assign(fit.error.begin(), fit.error.end());
  out.value.back() = std::exp(fit.value[fit.value.size() - 1]);
  out.error.back() = out.value.back() * fit.error[fit.error.size() - 1];
  out.scatter = fit.fitted() ? s : std::nan("");
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
  const CurveFit fit = fit_curve(law.model, p.t, p.y, {}, law.start(series_ends(p)));
  if (!fit.fitted()) return reported(fit, 0.0);
  return reported(fit, scatter(law, fit, p));
}

}  // namespace granpipe::compaction
