#include "volume_distribution.hpp"

#include <cmath>
#include <string>

namespace granpipe::pores {

VolumeDistribution::VolumeDistribution(double bin_width, double v_max, double v_tail)
    : bin_width_(bin_width), v_tail_(v_tail) {
  const auto bins = static_cast<std::size_t>(std::ceil(v_max / bin_width - 1e-9));
  counts_.assign(bins, 0.0);
  volumes_.assign(bins, 0.0);
}

void VolumeDistribution::add(const std::vector<double>& xi) {
  for (double x : xi) {
    ++pores_;
    const double v = x * x * x;
    if (v < 0.0) continue;  // overlapping soft spheres: no volume to weigh
    const auto k = static_cast<std::size_t>(v / bin_width_);
    if (k >= counts_.size()) continue;
    counts_[k] += 1.0;
    volumes_[k] += v;
  }
}

std::vector<double> VolumeDistribution::density() const {
  std::vector<double> rho(counts_.size(), std::nan(""));
  if (pores_ == 0) return rho;
  for (std::size_t k = 0; k < rho.size(); ++k)
    rho[k] = volumes_[k] / (static_cast<double>(pores_) * bin_width_);
  return rho;
}

CurveFit VolumeDistribution::tail_fit(double nu) const {
  const std::vector<double> rho = density();
  std::vector<double> v, y, sigma;
  for (std::size_t k = 0; k < rho.size(); ++k) {
    if (centre(k) < v_tail_ || counts_[k] == 0.0) continue;
    v.push_back(centre(k));
    y.push_back(rho[k]);
    sigma.push_back(rho[k] / std::sqrt(counts_[k]));
  }
  const CurveModel exponential{
      [](const Eigen::VectorXd& p, double x) { return p[0] * std::exp(-x / p[1]); },
      [](const Eigen::VectorXd& p, double x) {
        const double e = std::exp(-x / p[1]);
        Eigen::VectorXd g(2);
        g << e, p[0] * e * x / (p[1] * p[1]);
        return g;
      }};
  // From lambda = nu (the paper's law) through the first tail point.
  Eigen::VectorXd start(2);
  const double lambda = std::isfinite(nu) && nu > 0.0 ? nu : 0.1;
  start << (y.empty() ? 1.0 : y.front() * std::exp(v.front() / lambda)), lambda;
  return fit_curve(exponential, v, y, sigma, start);
}

CurveFitStatus VolumeDistribution::report(Results& results, double nu) const {
  Table t({"v", "count", "rho_v", "rho_v_err"},
          "volume distribution of the pores in v = xi^3, weighted by volume: rho_v = xi/3 P(xi)");
  const std::vector<double> rho = density();
  for (std::size_t k = 0; k < rho.size(); ++k) {
    const double err = counts_[k] > 0.0 ? rho[k] / std::sqrt(counts_[k]) : std::nan("");
    t.add_row({centre(k), counts_[k], rho[k], err});
  }
  results.add_table("volume_distribution", std::move(t));
  const CurveFit fit = tail_fit(nu);
  results.add_fit("rho_v_tail",
                  result_fit(fit, "rho_v(v) = A exp(-v / lambda), v >= v_tail", {"A", "lambda"}));
  results.add_scalar("rho_v_tail_status", static_cast<double>(fit.status), std::nan(""), "",
                     "the fit of rho_v's tail (its points: the non-empty bins from v_tail up): " +
                         describe(fit.status) + kCurveFitStatusCodes);
  return fit.status;
}

}  // namespace granpipe::pores
