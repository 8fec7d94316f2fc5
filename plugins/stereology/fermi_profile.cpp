#include "fermi_profile.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::stereology {
namespace {

// 1 / (1 + exp(t)) without overflow for large |t|.
double logistic_down(double t) {
  if (t > 0.0) {
    const double e = std::exp(-t);
    return e / (1.0 + e);
  }
  return 1.0 / (1.0 + std::exp(t));
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const auto middle = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

}  // namespace

CurveModel fermi_model() {
  return {[](const Eigen::VectorXd& p, double z) {
            return (p[kPhi0] - p[kAlpha] * z) * logistic_down(p[kBeta] * (z - p[kZstar]));
          },
          [](const Eigen::VectorXd& p, double z) {
            const double s = logistic_down(p[kBeta] * (z - p[kZstar]));
            const double bulk = p[kPhi0] - p[kAlpha] * z, slope = bulk * s * (1.0 - s);
            Eigen::VectorXd g(kFermiParameters);
            g << s, -z * s, -slope * (z - p[kZstar]), slope * p[kBeta];
            return g;
          }};
}

CurveFit fit_fermi_profile(const std::vector<double>& z, const std::vector<double>& phi,
                           double from) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < z.size() && k < phi.size(); ++k) {
    if (z[k] >= from) {
      x.push_back(z[k]);
      y.push_back(phi[k]);
    }
  }
  // The bins above the surface are empty; the bulk is the median of the others.
  std::vector<double> filled;
  for (double v : y)
    if (v > 0.0) filled.push_back(v);
  const double phi0 = median(filled);
  double zstar = x.empty() ? 0.0 : x.back();
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (y[k] < 0.5 * phi0) {
      zstar = x[k];
      break;
    }
  }
  Eigen::VectorXd start(kFermiParameters);
  start << phi0, 0.0, 1.0, zstar;
  if (!std::isfinite(phi0)) return fit_curve(fermi_model(), {}, {}, {}, start);
  return fit_curve(fermi_model(), x, y, {}, start);
}

}  // namespace granpipe::stereology
