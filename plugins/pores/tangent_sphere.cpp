#include "tangent_sphere.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace granpipe::pores {

namespace {

// The real roots of a x^2 + b x + c, without the cancellation of the schoolbook formula.
std::vector<double> quadratic_roots(double a, double b, double c) {
  if (a == 0.0) return b == 0.0 ? std::vector<double>{} : std::vector<double>{-c / b};
  const double discriminant = b * b - 4.0 * a * c;
  if (discriminant < 0.0) return {};
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  if (q == 0.0) return {0.0};
  return {q / a, c / q};
}

}  // namespace

std::optional<TangentSphere> tangent_sphere(const std::array<Eigen::Vector3d, 4>& centres,
                                            const std::array<double, 4>& radii) {
  // Relative to the first centre, for precision: u = c - x_0 = A + rho B.
  Eigen::Matrix3d m;
  Eigen::Vector3d d, e;
  for (int i = 1; i < 4; ++i) {
    const Eigen::Vector3d y = centres[i] - centres[0];
    m.row(i - 1) = 2.0 * y.transpose();
    d[i - 1] = y.squaredNorm() - (radii[i] * radii[i] - radii[0] * radii[0]);
    e[i - 1] = -2.0 * (radii[i] - radii[0]);
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::Vector3d a = lu.solve(d), b = lu.solve(e);
  const double r0 = radii[0];
  // |A + rho B|^2 = (r_0 + rho)^2
  const std::vector<double> roots =
      quadratic_roots(b.squaredNorm() - 1.0, 2.0 * (a.dot(b) - r0), a.squaredNorm() - r0 * r0);
  const double smallest_radius = *std::min_element(radii.begin(), radii.end());
  double best = std::numeric_limits<double>::infinity();
  for (double rho : roots)
    if (rho > -smallest_radius) best = std::min(best, rho);
  if (!std::isfinite(best)) return std::nullopt;
  return TangentSphere{centres[0] + a + best * b, best};
}

}  // namespace granpipe::pores
