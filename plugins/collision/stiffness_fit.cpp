#include "stiffness_fit.hpp"

#include <cmath>

namespace granpipe::collision {

void StiffnessFit::add(double delta, double normal_velocity, double normal_force) {
  const double v = -normal_velocity;
  dd_ += delta * delta;
  dv_ += delta * v;
  vv_ += v * v;
  df_ += delta * normal_force;
  vf_ += v * normal_force;
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

std::optional<double> StiffnessFit::determinant() const {
  const double det = dd_ * vv_ - dv_ * dv_;
  // Collinear regressors (relative to their scale): the two terms cannot be told apart.
  if (samples_ < 3 || !(det > 1e-12 * dd_ * vv_)) return {};
  return det;
}

}  // namespace granpipe::collision
