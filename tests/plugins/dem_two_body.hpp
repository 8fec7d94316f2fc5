#pragma once
// Two-body helpers of the dem contact tests: a material, a Contact of chosen parts, and a
// head-on collision whose relative coordinate is integrated with the evaluator's force alone.
#include <algorithm>

#include "contact_evaluator.hpp"

namespace dem_test {

namespace dem = granpipe::dem;
using dem::ScalarMath;
using dem::Vec4;

constexpr double kKn = 2e5;

inline dem::ContactMaterial material(double gamma_n, double mu, double mu_roll = 0.0) {
  dem::ContactMaterial m;
  m.kn = kKn;
  m.kt = 2.0 / 7.0 * kKn;
  m.gamma_n = gamma_n;
  m.gamma_t = 0.5 * gamma_n;
  m.mu = mu;
  m.mu_roll = mu_roll;
  return m;
}

template <class Normal, class Tangential = dem::NoFriction, class Rolling = dem::NoRolling,
          bool kRotation = false>
using ContactOf = dem::Contact<Normal, Tangential, Rolling, kRotation>;

// ---- Two bodies driven by the evaluator alone ------------------------------------------

struct Collision {
  double contact_time, restitution, peak_overlap;
};

// A head-on collision of two bodies of effective mass m_eff and contact diameter d at
// approach speed 1, its relative coordinate integrated by the engine's scheme (velocity
// Verlet, the force taken at the half-step velocity) with the evaluator's normal force.
template <class C>
Collision evaluator_collision(const dem::ContactMaterial& m, double m_eff, double d, double dt) {
  const dem::LoopMaterial loop = dem::loop_material(m);
  const auto accel = [&](double delta, double vn) {
    if (delta <= 0.0) return 0.0;
    dem::ContactInput<ScalarMath> in{};
    in.n = Vec4(1, 0, 0, 0);
    in.delta = delta;
    in.d = d;
    in.v_rel = Vec4(vn, 0, 0, 0);
    in.spin = Vec4::Zero();
    in.m_eff = m_eff;
    dem::ContactHistory<ScalarMath> h{Vec4::Zero(), Vec4::Zero()};
    return C::template evaluate<ScalarMath>(in, loop, h, dt).force[0] / m_eff;
  };
  // vn = d(x_i - x_j)/dt . n < 0 while approaching; delta' = -vn.
  double delta = 0.0, vn = -1.0, a = 0.0, t = 0.0, peak = 0.0;
  while (true) {
    const double half = vn + 0.5 * dt * a;
    const double next = delta - dt * half;
    a = accel(next, half);
    vn = half + 0.5 * dt * a;
    t += dt;
    peak = std::max(peak, next);
    if (next <= 0.0 && t > dt) {
      // The overlap's zero crossing, linearly between the two steps.
      return {t - dt + dt * delta / (delta - next), vn, peak};
    }
    delta = next;
  }
}

}  // namespace dem_test
