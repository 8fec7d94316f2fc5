#pragma once
// The parts a contact is composed of (contact_evaluator.hpp puts them together): one normal
// law, one tangential part and one rolling part, each a struct that declares
//   - the material fields it reads (MaterialOf below; ContactMaterial in model.hpp),
//   - kHistory: the doubles it keeps per contact from step to step (0 or one 3-vector),
//   - its force (or torque) for one contact or one contact per lane (template on the
//     arithmetic, contact_math.hpp), written once for the pair loop and the walls,
//   - its elastic energy and the shortest duration it gives a two-body contact, which the
//     energy diagnostics and the time-step check sum or compare over the parts.
// The paper's law (Sun, Battaglia and Subramaniam 2006, Sec. II, Eqs. 1-6): the normal
// force f(delta/d) (k_n delta - gamma_n m_eff v_n) with f = 1 (linear spring-dashpot) or
// sqrt(delta/d) (Hertz), d = R_i + R_j (for a wall: d = 2 R_i, the particle's mirror
// image); the tangential force f(delta/d) (-k_t u - gamma_t m_eff v_t), |F_t| <= mu |F_n|.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model.hpp"
#include "vec4.hpp"

namespace granpipe::dem {

// The normal laws the `law` parameter names (contact_evaluator.hpp maps each to its part).
enum class ContactLaw { Linear, Hertz };

// A contact's material as the force loops read it: R is a double (walls) or one value per
// lane (pairs). The fields are read by position (kernels.cpp), grouped by part.
template <class R>
struct MaterialOf {
  R kn, kt, gamma_n, gamma_t, mu, inv_kt;  // normal and tangential parts
  R mu_roll, k_roll;                       // rolling part: k_roll R_eff^2 is its stiffness
};
using LoopMaterial = MaterialOf<double>;
inline constexpr int kMaterialFields = sizeof(LoopMaterial) / sizeof(double);
// The fields before the rolling part's: what a loop without rolling resistance reads.
inline constexpr int kMaterialFieldsWithoutRolling = 6;

// The two bodies of a contact, for the durations and energies the parts declare: effective
// mass and moment of inertia (a wall counts as infinitely heavy: those of the particle),
// d = R_i + R_j (2 R_i against a wall), R_eff = R_i R_j / (R_i + R_j) (R_i against a wall),
// and the normal speed of impact (the Hertz contact's duration depends on it).
struct TwoBodies {
  double m_eff, i_eff, d, r_eff, speed;
};

// ---- Normal laws -----------------------------------------------------------------------

// f = 1. Functions of M:: are the arithmetic of contact_math.hpp.
struct LinearNormal {
  static constexpr bool kDurationNeedsSpeed = false;
  template <class M>
  static typename M::Real factor(const typename M::Real& /*delta*/, const typename M::Real& /*d*/) {
    return M::splat(1.0);
  }
  // f x, and x / f: the linear law skips them (multiplying by 1 changes no bit).
  template <class R, class T>
  static T scaled(const R& /*f*/, const T& x) {
    return x;
  }
  template <class M>
  static typename M::Vec unscaled(const typename M::Real& /*f*/, const typename M::Vec& x) {
    return x;
  }
  static double potential(const ContactMaterial& m, double delta, double /*d*/) {
    return 0.5 * m.kn * delta * delta;
  }
  // Eq. (10), the damped oscillator's half period, or the dashpot's time where shorter
  // (near and past critical damping).
  static double contact_time(const ContactMaterial& m, const TwoBodies& b) {
    return std::min(spring_half_period(m.kn, m.gamma_n, b.m_eff, b), dashpot_time(m.gamma_n));
  }
  // The half period of a spring of stiffness k of this law's shape with a dashpot of this
  // rate on this mass (the tangential spring's too): Eq. (10).
  static double spring_half_period(double k, double rate, double mass, const TwoBodies& /*b*/) {
    return linear_contact_time(k, rate, mass);
  }
  // The undamped overlap of a body of this mass hit at this speed, and at rest under this
  // weight; the speed and weight that give an overlap grow as its power below.
  static double impact_overlap(double kn, double mass, double speed, double /*d*/) {
    return speed * std::sqrt(mass / kn);
  }
  static double rest_overlap(double kn, double weight, double /*d*/) { return weight / kn; }
  static constexpr double kSpeedPerOverlapExponent = 1.0;
  static constexpr double kWeightPerOverlapExponent = 1.0;
};

// f = sqrt(delta/d).
struct HertzNormal {
  static constexpr bool kDurationNeedsSpeed = true;
  template <class M>
  static typename M::Real factor(const typename M::Real& delta, const typename M::Real& d) {
    return M::sqrt(delta / d);
  }
  template <class R, class T>
  static T scaled(const R& f, const T& x) {
    return f * x;
  }
  template <class M>
  static typename M::Vec unscaled(const typename M::Real& f, const typename M::Vec& x) {
    return M::divide(x, f);
  }
  static double potential(const ContactMaterial& m, double delta, double d) {
    return 0.4 * m.kn * delta * delta * std::sqrt(delta / d);
  }
  // Undamped, at the impact speed (model.hpp), or the dashpot's time where shorter (its
  // rate gamma_n f is at most gamma_n: delta < d).
  static double contact_time(const ContactMaterial& m, const TwoBodies& b) {
    return std::min(spring_half_period(m.kn, m.gamma_n, b.m_eff, b), dashpot_time(m.gamma_n));
  }
  static double spring_half_period(double k, double /*rate*/, double mass, const TwoBodies& b) {
    return hertz_contact_time(k, b.d, mass, b.speed);
  }
  static double impact_overlap(double kn, double mass, double speed, double d) {
    return std::pow(5.0 * mass * speed * speed * std::sqrt(d) / (4.0 * kn), 0.4);
  }
  static double rest_overlap(double kn, double weight, double d) {
    return std::pow(weight * std::sqrt(d) / kn, 2.0 / 3.0);
  }
  static constexpr double kSpeedPerOverlapExponent = 1.25;
  static constexpr double kWeightPerOverlapExponent = 1.5;
};

// ---- Tangential parts ------------------------------------------------------------------

struct NoFriction {
  static constexpr bool kActive = false;
  static constexpr int kHistory = 0;
};

// The elastic displacement u of Eq. (4), kept for the life of the contact. Each step u is
// first projected onto the current tangent plane (the rigid-rotation term of Eq. 4, which
// turns u with the contact: projecting loses a fraction theta^2/2 of |u| per step for a
// turn theta of the normal, 1e-7 at the Brazil-nut scene's speeds, as in LAMMPS), then
// advanced by v_t dt; if the trial force f(-k_t u - gamma_t m_eff v_t) exceeds mu |F_n| it
// is scaled back onto the Coulomb cone and u is set to the displacement that gives exactly
// that force (as LAMMPS' gran/hooke/history does).
struct CoulombSpring {
  static constexpr bool kActive = true;
  static constexpr int kHistory = 3;

  // The tangential force; u is advanced in place. vt: the tangential slip velocity.
  template <class Normal, class M>
  [[gnu::always_inline]] static typename M::Vec force(
      const typename M::Real& f, const typename M::Real& fn, const typename M::Vec& n,
      const typename M::Vec& vt, const typename M::Real& m_eff,
      const MaterialOf<typename M::Real>& m, typename M::Vec& u, const typename M::Real& dt) {
    using Real = typename M::Real;
    using Vec = typename M::Vec;
    Vec ut = u - M::dot(u, n) * n;
    ut = ut + dt * vt;
    const Real damping = m.gamma_t * m_eff;
    const Vec trial = Normal::scaled(f, Vec(-(m.kt * ut + damping * vt)));
    const Real limit = m.mu * M::abs(fn);
    const Real ft2 = M::dot(trial, trial);
    const auto sliding = ft2 > limit * limit;
    // Computed whether or not the contact slides (in the pair loop a square root and a
    // division per batch, not per contact), kept only where it does. f > 0 (delta > 0).
    const Vec capped = (limit / M::sqrt(ft2)) * trial;
    const Vec spring = Normal::template unscaled<M>(f, capped);
    u = M::select(sliding, Vec(-(m.inv_kt * (spring + damping * vt))), ut);
    return M::select(sliding, capped, trial);
  }

  static double potential(const ContactMaterial& m, double f, const Vec3& u) {
    return 0.5 * f * m.kt * u.squaredNorm();
  }
  // The spring acts on m_t = 2/7 m_eff (rotation included, for spheres), with the normal
  // law's shape, and its dashpot at the rate gamma_t m_eff / m_t = 7/2 gamma_t: no shorter
  // than the normal contact with k_t <= 2/7 k_n and gamma_t >= 2/7 gamma_n (the paper's),
  // shorter with a stiffer spring (k_t = 1e8 against k_n = 2e5 went unchecked and blew the
  // run up, the message advising a stiffer k_n). Neither acts without friction (the force
  // capped at mu |F_n| = 0).
  template <class Normal>
  static double contact_time(const ContactMaterial& m, const TwoBodies& b) {
    if (!(m.mu > 0.0)) return std::numeric_limits<double>::infinity();
    const double rate = 3.5 * m.gamma_t;
    const double spring = m.kt > 0.0
                              ? Normal::spring_half_period(m.kt, rate, 2.0 / 7.0 * b.m_eff, b)
                              : std::numeric_limits<double>::infinity();
    return std::min(spring, dashpot_time(rate));
  }
};

// ---- Rolling parts ---------------------------------------------------------------------

struct NoRolling {
  static constexpr bool kActive = false;
  static constexpr int kHistory = 0;
};

// Rolling resistance, the elastic-plastic spring without dashpot (LIGGGHTS' `rolling_friction
// epsd2`, after Iwashita and Oda; the spring-dashpot family is model C of Ai et al., Powder
// Technol. 206, 2011): the relative rotation theta (the integral of w_i - w_j) is kept for
// the life of the contact like u, and gives the torque -f k_r theta on i (minus it on the
// partner), k_r = k_t R_eff^2, capped at mu_r R_eff |F_n| (theta then set to what gives
// exactly the cap). At the cap a rolling sphere feels the constant torque mu_r R_eff |F_n|
// against its rolling; below it the spring holds a rattler still instead of letting it
// rock. Twisting (turning about n) is resisted alike (LIGGGHTS' torsionTorque on): the
// rattlers of a settled bed that keep turning are spheres spinning about the normal of
// their one contact (on the base) or of two opposite ones (docs/dem.md).
struct RollingSpring {
  static constexpr bool kActive = true;
  static constexpr int kHistory = 3;

  // The torque on i; theta is advanced in place. w_rel = w_i - w_j.
  template <class Normal, class M>
  [[gnu::always_inline]] static typename M::Vec torque(
      const typename M::Real& f, const typename M::Real& fn, const typename M::Vec& w_rel,
      const typename M::Real& r_eff, const MaterialOf<typename M::Real>& m, typename M::Vec& theta,
      const typename M::Real& dt) {
    using Real = typename M::Real;
    using Vec = typename M::Vec;
    const Vec turned = theta + dt * w_rel;
    const Real kr = m.k_roll * r_eff * r_eff;
    const Vec trial = Normal::scaled(f, Vec(-(kr * turned)));
    const Real limit = m.mu_roll * r_eff * M::abs(fn);
    const Real t2 = M::dot(trial, trial);
    const auto rolling_plastic = t2 > limit * limit;
    const Vec capped = (limit / M::sqrt(t2)) * trial;
    theta = M::select(rolling_plastic,
                      Vec(-(Real(1.0 / kr) * Normal::template unscaled<M>(f, capped))), turned);
    return M::select(rolling_plastic, capped, trial);
  }

  static double stiffness(const ContactMaterial& m, double r_eff) { return m.kt * r_eff * r_eff; }
  static double potential(const ContactMaterial& m, double f, double r_eff, const Vec3& theta) {
    return 0.5 * f * stiffness(m, r_eff) * theta.squaredNorm();
  }
  // Half the period of the undamped rolling spring, I_eff theta'' = -k_r theta (f = 1); none
  // without rolling friction.
  static double contact_time(const ContactMaterial& m, const TwoBodies& b) {
    const double kr = stiffness(m, b.r_eff);
    if (m.mu_roll == 0.0 || kr == 0.0) return std::numeric_limits<double>::infinity();
    return std::numbers::pi * std::sqrt(b.i_eff / kr);
  }
};

// The material of a contact as the force loops read it (kt's inverse precomputed).
inline LoopMaterial loop_material(const ContactMaterial& m) {
  return {m.kn,      m.kt,
          m.gamma_n, m.gamma_t,
          m.mu,      m.kt > 0.0 ? 1.0 / m.kt : 0.0,
          m.mu_roll, RollingSpring::stiffness(m, 1.0)};
}

}  // namespace granpipe::dem
