#pragma once
// The normal stiffness and damping of the law that made the frames, measured from them:
// in contact, the linear law's normal force is F = k_n delta - c v_n (c = gamma_n m_eff,
// v_n < 0 approaching), so a least-squares fit of the frames' normal forces against the
// overlap and the normal velocity gives k_n and c. The analyzer's analytic values are only
// the source's when its k_n, gamma_n and density are: this is how other values are caught,
// since a frame does not carry the source's parameters.
#include <cstddef>
#include <optional>

namespace granpipe::collision {

class StiffnessFit {
 public:
  // One frame in contact: overlap delta > 0, normal velocity v_n, normal force on the pair
  // along the normal (repulsive > 0).
  void add(double delta, double normal_velocity, double normal_force);
  std::size_t samples() const { return samples_; }
  // k_n; nothing with fewer than 3 samples or overlaps and velocities that do not tell the
  // two terms apart.
  std::optional<double> stiffness() const;
  // c = gamma_n m_eff, likewise.
  std::optional<double> damping() const;
  // The root mean square of what the fitted line leaves of the forces, over the root mean
  // square force: rounding for frames of the linear law, a few hundredths for Hertz's
  // F ~ delta^(3/2). Nothing where stiffness() and damping() are nothing.
  std::optional<double> relative_residual() const;

 private:
  std::optional<double> determinant() const;
  // Sums of the normal equations for (k_n, c) with regressors delta and -v_n.
  double dd_ = 0.0, dv_ = 0.0, vv_ = 0.0, df_ = 0.0, vf_ = 0.0, ff_ = 0.0;
  std::size_t samples_ = 0;
};

}  // namespace granpipe::collision
