#pragma once
// One contact, resolved: the force law of the paper (Sec. II, Eqs. 1-6) as compile-time
// policies, shared by particle-particle and particle-wall contacts.
//
// Normal law (policy Law): f(delta/d) = 1 (Linear, spring-dashpot) or sqrt(delta/d)
// (Hertz), d = R_i + R_j (for a wall: d = 2 R_i, the particle's mirror image).
// Tangential (kFriction): the elastic displacement u of Eq. (4), kept for the life of the
// contact. Each step u is first projected onto the current tangent plane (the
// rigid-rotation term of Eq. 4, which turns u with the contact: projecting loses a
// fraction theta^2/2 of |u| per step for a turn theta of the normal, 1e-7 at the
// Brazil-nut scene's speeds, as in LAMMPS), then advanced by v_t dt; if the trial force
// f(-k_t u - gamma_t m_eff v_t) exceeds mu |F_n| it is scaled back onto the Coulomb
// cone and u is set to the displacement that gives exactly that force (as LAMMPS'
// gran/hooke/history does).
// Rotation (kRotation): v_t includes -(R_i w_i + R_j w_j) x n (Eq. 3); without it, spins
// are ignored (sliding blocks rather than spheres).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace granpipe::dem {

using Vec3 = Eigen::Vector3d;

enum class ContactLaw { Linear, Hertz };

struct LinearLaw {
  static constexpr ContactLaw kind = ContactLaw::Linear;
  static double scale(double /*delta*/, double /*d*/) { return 1.0; }
};
struct HertzLaw {
  static constexpr ContactLaw kind = ContactLaw::Hertz;
  static double scale(double delta, double d) { return std::sqrt(delta / d); }
};

// A material ready for the force loop (kt's inverse precomputed).
struct LoopMaterial {
  double kn, kt, gamma_n, gamma_t, mu, inv_kt;
};

// The force on particle i from the contact and c = n x F_t (the torque on i is -R_i c, the
// torque on the partner -R_j c: Eq. 8). n points from the partner to i; delta > 0.
struct ContactForce {
  Vec3 force;
  Vec3 normal;  // the normal part of `force`
  Vec3 c;
};

// v_rel: v_i - v_j (translational); spin: R_i w_i + R_j w_j; u: the stored displacement
// (3 doubles, updated in place; unused without friction); dt_history: the time step, or 0
// for a force evaluation that must not advance the history (the initial one).
template <class Law, bool kFriction, bool kRotation>
[[gnu::always_inline]] inline ContactForce resolve_contact(const Vec3& n, double delta, double d, const Vec3& v_rel,
                                    const Vec3& spin, double m_eff, const LoopMaterial& m,
                                    double* u, double dt_history) {
  static_assert(kFriction || !kRotation, "rotation without friction has no torque to apply");
  const double f = Law::scale(delta, d);
  const double vn = v_rel.dot(n);
  const double fn = f * (m.kn * delta - m.gamma_n * m_eff * vn);
  ContactForce out;
  out.normal = fn * n;
  if constexpr (!kFriction) {
    out.force = out.normal;
    return out;
  } else {
    Vec3 vt = v_rel - vn * n;
    if constexpr (kRotation) vt -= spin.cross(n);
    Vec3 ut(u[0], u[1], u[2]);
    ut -= ut.dot(n) * n;
    ut += dt_history * vt;
    Vec3 ft = -f * (m.kt * ut + m.gamma_t * m_eff * vt);
    const double limit = m.mu * std::abs(fn);
    const double ft2 = ft.squaredNorm();
    if (ft2 > limit * limit) {
      ft *= limit / std::sqrt(ft2);
      // f > 0 here (delta > 0); without a tangential spring there is nothing to keep.
      ut = -(ft / f + m.gamma_t * m_eff * vt) * m.inv_kt;
    }
    u[0] = ut[0];
    u[1] = ut[1];
    u[2] = ut[2];
    out.force = out.normal + ft;
    out.c = n.cross(ft);
    return out;
  }
}

}  // namespace granpipe::dem
