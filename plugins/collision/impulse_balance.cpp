#include "impulse_balance.hpp"

#include <algorithm>

namespace granpipe::collision {

double ImpulseBalance::add(double time, const Eigen::Vector3d& relative_velocity, bool touching,
                           const Eigen::Vector3d& force) {
  double free_flight_change = 0.0;
  if (!started_) {
    started_ = true;
    first_velocity_ = relative_velocity;
  } else {
    const double dt = time - last_time_;
    impulse_ += 0.5 * (last_force_ + force) * dt;
    if (last_touching_ != touching) ends_ += 0.5 * (last_force_ + force).norm() * dt;
    if (!last_touching_ && !touching)
      free_flight_change = (relative_velocity - last_velocity_).norm();
  }
  last_time_ = time;
  last_velocity_ = relative_velocity;
  last_force_ = force;
  last_touching_ = touching;
  return free_flight_change;
}

Eigen::Vector3d ImpulseBalance::momentum_change(double m_eff) const {
  return m_eff * (last_velocity_ - first_velocity_);
}

bool ImpulseBalance::holds(double m_eff) const {
  const Eigen::Vector3d change = momentum_change(m_eff);
  const double scale = std::max(change.norm(), impulse_.norm());
  return (change - impulse_).norm() <= kImpulseTolerance * scale + ends_;
}

}  // namespace granpipe::collision
