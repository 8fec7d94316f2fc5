#include "compaction_laws.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::compaction {

namespace {

// L = ln(1 + t/tau) and its derivative with respect to ln(tau).
struct LogTime {
  double value, by_log_tau;
  LogTime(double t, double log_tau) {
    const double u = t / std::exp(log_tau);
    value = std::log1p(u);
    by_log_tau = -u / (1.0 + u);
  }
};

// ln(1 + t_last/tau) at the start's tau = 1 tap.
double start_log_time(const SeriesEnds& e) { return std::log1p(std::max(e.t_last, 1.0)); }

double eq3_value(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[3]);
  return p[0] - p[1] / (1.0 + p[2] * L.value);
}

Eigen::VectorXd eq3_gradient(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[3]);
  const double d = 1.0 + p[2] * L.value;
  Eigen::VectorXd g(4);
  g << 1.0, -1.0 / d, p[1] * L.value / (d * d), p[1] * p[2] * L.by_log_tau / (d * d);
  return g;
}

// X_0 = X_inf - dX through the first point; X_inf - dX/(1 + L) through the last.
Eigen::VectorXd eq3_start(const SeriesEnds& e) {
  const double L = start_log_time(e);
  const double dx = (e.y_last - e.y_first) * (1.0 + L) / L;
  Eigen::VectorXd p(4);
  p << e.y_first + dx, dx, 1.0, 0.0;
  return p;
}

double eq4_value(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[3]);
  return p[0] * (1.0 + p[2] * L.value) / (p[0] / p[1] + p[2] * L.value);
}

Eigen::VectorXd eq4_gradient(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[3]);
  const double n = 1.0 + p[2] * L.value, m = p[0] / p[1] + p[2] * L.value;
  const double z_inf = p[0], z_0 = p[1];
  Eigen::VectorXd g(4);
  g << n / m * (1.0 - z_inf / (z_0 * m)), z_inf * z_inf * n / (m * m * z_0 * z_0),
      z_inf * L.value * (m - n) / (m * m), z_inf * p[2] * (m - n) / (m * m) * L.by_log_tau;
  return g;
}

// Z_0 the first point; Z_inf such that the curve passes through the last:
// Z_last (Z_inf/Z_0 + L) = Z_inf (1 + L).
Eigen::VectorXd eq4_start(const SeriesEnds& e) {
  const double L = start_log_time(e);
  const double denominator = 1.0 + L - e.y_last / e.y_first;
  const double z_inf = denominator > 0.0 ? e.y_last * L / denominator : e.y_last;
  Eigen::VectorXd p(4);
  p << z_inf, e.y_first, 1.0, 0.0;
  return p;
}

double eq6_value(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[2]);
  return p[0] * (1.0 - 1.0 / (1.0 + p[1] * L.value));
}

Eigen::VectorXd eq6_gradient(const Eigen::VectorXd& p, double t) {
  const LogTime L(t, p[2]);
  const double d = 1.0 + p[1] * L.value;
  Eigen::VectorXd g(3);
  g << 1.0 - 1.0 / d, p[0] * L.value / (d * d), p[0] * p[1] * L.by_log_tau / (d * d);
  return g;
}

// A(0) = 0 whatever the parameters; A_inf L/(1 + L) through the last point.
Eigen::VectorXd eq6_start(const SeriesEnds& e) {
  const double L = start_log_time(e);
  Eigen::VectorXd p(3);
  p << e.y_last * (1.0 + L) / L, 1.0, 0.0;
  return p;
}

}  // namespace

const Law& eq3_law() {
  static const Law law{"X(t) = X_inf - dX_inf / (1 + B ln(1 + t/tau))",
                       {"X_inf", "dX_inf", "B", "tau"},
                       {eq3_value, eq3_gradient},
                       eq3_start};
  return law;
}

const Law& eq4_law() {
  static const Law law{"<Z>(t) = Z_inf (1 + B ln(1 + t/tau)) / (Z_inf/Z_0 + B ln(1 + t/tau))",
                       {"Z_inf", "Z_0", "B", "tau"},
                       {eq4_value, eq4_gradient},
                       eq4_start};
  return law;
}

const Law& eq6_law() {
  static const Law law{"A(t) = A_inf (1 - 1 / (1 + B ln(1 + t/tau)))",
                       {"A_inf", "B", "tau"},
                       {eq6_value, eq6_gradient},
                       eq6_start};
  return law;
}

}  // namespace granpipe::compaction
