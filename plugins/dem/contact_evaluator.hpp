#pragma once
// One contact, evaluated: the parts of contact_parts.hpp put together, written once for
// the pair loop (one contact per lane, LaneMath) and the walls (one contact, ScalarMath),
// as HOOMD-blue's pair evaluators are written once for every loop that calls them and
// LIGGGHTS composes its granular models from normal, tangential and rolling parts.
//
// Contact<Normal, Tangential, Rolling, kRotation> is a compile-time policy: the kernels are
// instantiated per combination (kernels.hpp), so an absent part costs nothing in the loop.
// Rotation (kRotation): the slip velocity includes -(R_i w_i + R_j w_j) x n (Eq. 3); without
// it, spins are ignored (sliding blocks rather than spheres).
//
// The one place a law's name becomes its part is with_contact_law() below: a new normal law
// is a part, a case there and a schema choice; a new tangential or rolling part is a part,
// its material field(s) and schema entry, and the combinations select_kernels() compiles.
#include <algorithm>
#include <stdexcept>

#include "contact_math.hpp"
#include "contact_parts.hpp"

namespace granpipe::dem {

// What the evaluator reads of one contact (per lane for LaneMath). n points from the
// partner to i; delta > 0; v_rel = v_i - v_j (translational); spin = R_i w_i + R_j w_j;
// w_rel = w_i - w_j and r_eff are read by a rolling part only.
template <class M>
struct ContactInput {
  typename M::Vec n;
  typename M::Real delta, d;
  typename M::Vec v_rel, spin;
  typename M::Real m_eff;
  typename M::Vec w_rel;
  typename M::Real r_eff;
};

// What the parts keep from step to step: the tangential displacement u and the rolling
// angle theta (each read and written by its part only).
template <class M>
struct ContactHistory {
  typename M::Vec u, theta;
};

// The elastic energy each part stores in one contact.
struct ContactEnergy {
  double normal = 0.0, tangential = 0.0, rolling = 0.0;
};

// The force on i and its normal part, c = n x F_t (the torque on i is -R_i c, on the
// partner -R_j c: Eq. 8) and the rolling torque on i (on the partner: minus it).
template <class M>
struct ContactResult {
  typename M::Vec force, normal, c, roll;
};

template <class Normal, class Tangential, class Rolling, bool kRotation>
struct Contact {
  using NormalPart = Normal;
  static constexpr bool kFriction = Tangential::kActive;
  static constexpr bool kRolling = Rolling::kActive;
  static constexpr bool kSpin = kRotation;
  static_assert(kFriction || !kRotation, "rotation without friction has no torque to apply");
  static_assert(!kRolling || kRotation, "rolling resistance needs rotation");
  // The engine keeps one 3-vector per contact for each part that keeps a history (u in
  // NeighborList::history and Particles::wall_history, theta in the rolling_history arrays):
  // a part with another history needs its own arrays there.
  static_assert(Tangential::kHistory == (kFriction ? 3 : 0) &&
                    Rolling::kHistory == (kRolling ? 3 : 0),
                "a part's history is one 3-vector per contact, or none");
  // The material fields the loop reads.
  static constexpr int kFields = kRolling ? kMaterialFields : kMaterialFieldsWithoutRolling;

  // dt: the time step by which the histories advance (0 for an evaluation that must not
  // advance them: the initial one).
  template <class M>
  [[gnu::always_inline]] static ContactResult<M> evaluate(const ContactInput<M>& in,
                                                          const MaterialOf<typename M::Real>& m,
                                                          ContactHistory<M>& h,
                                                          const typename M::Real& dt) {
    using Real = typename M::Real;
    using Vec = typename M::Vec;
    const Real f = Normal::template factor<M>(in.delta, in.d);
    const Real vn = M::dot(in.v_rel, in.n);
    const Real fn = Normal::scaled(f, Real(m.kn * in.delta - m.gamma_n * in.m_eff * vn));
    ContactResult<M> out;
    out.normal = fn * in.n;
    if constexpr (!kFriction) {
      out.force = out.normal;
    } else {
      Vec vt = in.v_rel - vn * in.n;
      if constexpr (kRotation) vt = vt - M::cross(in.spin, in.n);
      const Vec ft = Tangential::template force<Normal, M>(f, fn, in.n, vt, in.m_eff, m, h.u, dt);
      out.force = out.normal + ft;
      out.c = M::cross(in.n, ft);
    }
    if constexpr (kRolling) {
      out.roll = Rolling::template torque<Normal, M>(f, fn, in.w_rel, in.r_eff, m, h.theta, dt);
    }
    return out;
  }

  // The elastic energy the parts store in one contact (u, theta: its histories).
  static ContactEnergy energy(const ContactMaterial& m, double delta, double d, double r_eff,
                              const Vec3& u, const Vec3& theta) {
    ContactEnergy e;
    e.normal = Normal::potential(m, delta, d);
    const double f = Normal::template factor<ScalarMath>(delta, d);
    if constexpr (kFriction) e.tangential = Tangential::potential(m, f, u);
    if constexpr (kRolling) e.rolling = Rolling::potential(m, f, r_eff, theta);
    return e;
  }

  // The shortest duration any part gives this two-body contact.
  static double contact_time(const ContactMaterial& m, const TwoBodies& b) {
    double t = Normal::contact_time(m, b);
    if constexpr (kFriction) t = std::min(t, Tangential::template contact_time<Normal>(m, b));
    if constexpr (kRolling) t = std::min(t, Rolling::contact_time(m, b));
    return t;
  }
};

// Calls f with the normal part of `law` (a value of its type).
template <class F>
decltype(auto) with_contact_law(ContactLaw law, F&& f) {
  switch (law) {
    case ContactLaw::Linear:
      return f(LinearNormal{});
    case ContactLaw::Hertz:
      return f(HertzNormal{});
  }
  throw std::logic_error("dem: a contact law without its normal part");
}

// Calls f with the Contact of this combination (a value of its type). Friction off serves
// rotation on too (no tangential force, so no torque); rolling needs friction and rotation
// (Engine refuses it otherwise).
template <class F>
decltype(auto) with_contact(ContactLaw law, bool friction, bool rotation, bool rolling, F&& f) {
  return with_contact_law(law, [&](auto normal) {
    using Normal = decltype(normal);
    if (!friction) return f(Contact<Normal, NoFriction, NoRolling, false>{});
    if (!rotation) return f(Contact<Normal, CoulombSpring, NoRolling, false>{});
    if (!rolling) return f(Contact<Normal, CoulombSpring, NoRolling, true>{});
    return f(Contact<Normal, CoulombSpring, RollingSpring, true>{});
  });
}

}  // namespace granpipe::dem
