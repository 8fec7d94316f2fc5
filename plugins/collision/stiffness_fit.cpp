#include "stiffness_fit.hpp"

#include <algorithm>
#include <cmath>

namespace granpipe::collision {

void StiffnessFit::add(double delta, double normal_velocity, double normal_force) {
  const double v = -normal_velocity;
  dd_ += delta * delta;
  dv_ += delta * v;
  vv_ += v * v;
  df_ += delta * normal_force;
  vf_ += v * normal_force;
  ff_ += normal_force * normal_force;
  ++samples_;
}

std::optional<double> StiffnessFit::stiffness() const {
  const auto det = determinant();
  if (!det) return {};
  return (df_ * vv_ - vf_ * dv_) / *det;
}

std::optional<double> StiffnessFit::damping() const {
  const auto det = determinant();
  if (!det) return {};
  return (dd_ * vf_ - dv_ * df_) / *det;
}

std::optional<double> StiffnessFit::relative_residual() const {
  const auto k = stiffness(), c = damping();
  if (!k || !c || !(ff_ > 0.0)) return {};
  // sum (f - k delta - c v)^2 from the sums, without the samples.
  const double left =
      ff_ - 2.0 * (*k * df_ + *c * vf_) + *k * *k * dd_ + 2.0 * *k * *c * dv_ + *c * *c * vv_;
  return std::sqrt(std::max(left, 0.0) / ff_);
}

std::optional<double> StiffnessFit::determinant() const {
  const double det = dd_ * vv_ - dv_ * dv_;
  // Collinear regressors (relative to their scale): the two terms cannot be told apart.
  if (samples_ < 3 || !(det > 1e-12 * dd_ * vv_)) return {};
  return det;
}

}  // namespace granpipe::collision
