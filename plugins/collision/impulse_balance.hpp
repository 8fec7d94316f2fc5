#pragma once
// The two spheres of a collision exchange momentum only through their contact: over the
// run, m_eff times the change of their relative velocity equals the impulse of the contact
// force. Velocity Verlet integrates the frames' forces by the trapezoid rule, so for its
// frames the two agree to rounding (dt = t_c/100 to t_c/10); for frames of the exact motion
// the trapezoid misplaces up to |F| dt / 2 where the force starts and stops (the dashpot's
// jump; with the curvature's error, 0.1 % at dt = t_c/20), which the comparison allows. A fixed
// sphere (twice the change for equal masses), a drag, or densities other than the source's (a wrong
// m_eff) break it, and the analytic contact time and restitution are then another pair's; a uniform
// gravity moves both spheres alike and leaves it.
#include <Eigen/Core>

namespace granpipe::collision {

// Rounding, as a fraction of the larger side, on top of the contact's ends.
constexpr double kImpulseTolerance = 1e-9;

class ImpulseBalance {
 public:
  // A frame at `time`: the spheres' relative velocity v_0 - v_1, whether they touch, and
  // the contact force on sphere 0. Returns how far the relative velocity moved since the
  // frame before when they touched in neither (free flight, where nothing may move it: a
  // drag does), else 0.
  double add(double time, const Eigen::Vector3d& relative_velocity, bool touching,
             const Eigen::Vector3d& force);
  // m_eff times the relative velocity's change from the first frame to the last.
  Eigen::Vector3d momentum_change(double m_eff) const;
  const Eigen::Vector3d& impulse() const { return impulse_; }
  // True when the two agree within kImpulseTolerance and what the trapezoid may misplace
  // at the contact's ends.
  bool holds(double m_eff) const;

 private:
  bool started_ = false;
  double last_time_ = 0.0;
  Eigen::Vector3d first_velocity_ = Eigen::Vector3d::Zero(), last_velocity_ = first_velocity_;
  Eigen::Vector3d last_force_ = first_velocity_, impulse_ = first_velocity_;
  bool last_touching_ = false;
  double ends_ = 0.0;  // |F| dt / 2 at each frame where the force starts or stops
};

}  // namespace granpipe::collision
