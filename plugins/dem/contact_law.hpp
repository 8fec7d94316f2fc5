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

#include "lanes.hpp"
#ifdef __AVX__
#include <immintrin.h>
#endif

namespace granpipe::dem {

using Vec3 = Eigen::Vector3d;
// The force loop's vectors: (x, y, z, 0). With AVX a 4-vector is one register, so each
// vector operation is one instruction, where a 3-vector takes a pair, a scalar and the
// shuffles between them; the zero keeps dot products and norms those of the 3-vector.
using Vec4 = Eigen::Vector4d;

enum class ContactLaw { Linear, Hertz };

struct LinearLaw {
  static constexpr ContactLaw kind = ContactLaw::Linear;
  static double scale(double /*delta*/, double /*d*/) { return 1.0; }
};
struct HertzLaw {
  static constexpr ContactLaw kind = ContactLaw::Hertz;
  static double scale(double delta, double d) { return std::sqrt(delta / d); }
};

// The padded vector of the 3 doubles at p. With AVX, one masked load: a vector assembled
// from scalars goes through the stack, and the wide load of narrower stores that follows
// stalls (it cannot be forwarded), which costs more than all the arithmetic here.
inline Vec4 load3(const double* p) {
#ifdef __AVX__
  Vec4 v;
  _mm256_storeu_pd(v.data(), _mm256_maskload_pd(p, _mm256_set_epi64x(0, -1, -1, -1)));
  return v;
#else
  return Vec4(p[0], p[1], p[2], 0.0);
#endif
}

// Stores the first 3 doubles of v at p: one masked store with AVX-512.
inline void store3(double* p, const Vec4& v) {
#ifdef __AVX512VL__
  _mm256_mask_storeu_pd(p, 0x7, _mm256_loadu_pd(v.data()));
#else
  p[0] = v[0];
  p[1] = v[1];
  p[2] = v[2];
#endif
}

// a x b of two padded vectors. With AVX2: two lane rotations per operand and a fused
// multiply-subtract (Eigen's cross3 works lane by lane for doubles).
inline Vec4 cross(const Vec4& a, const Vec4& b) {
#ifdef __AVX2__
  const __m256d pa = _mm256_loadu_pd(a.data()), pb = _mm256_loadu_pd(b.data());
  const __m256d a_yzx = _mm256_permute4x64_pd(pa, _MM_SHUFFLE(3, 0, 2, 1));
  const __m256d a_zxy = _mm256_permute4x64_pd(pa, _MM_SHUFFLE(3, 1, 0, 2));
  const __m256d b_yzx = _mm256_permute4x64_pd(pb, _MM_SHUFFLE(3, 0, 2, 1));
  const __m256d b_zxy = _mm256_permute4x64_pd(pb, _MM_SHUFFLE(3, 1, 0, 2));
  Vec4 out;
  _mm256_storeu_pd(out.data(), _mm256_fmsub_pd(a_yzx, b_zxy, _mm256_mul_pd(a_zxy, b_yzx)));
  return out;
#else
  return a.cross3(b);
#endif
}

// A material ready for the force loop (kt's inverse precomputed).
struct LoopMaterial {
  double kn, kt, gamma_n, gamma_t, mu, inv_kt;
};

// The force on particle i from the contact and c = n x F_t (the torque on i is -R_i c, the
// torque on the partner -R_j c: Eq. 8). n points from the partner to i; delta > 0.
struct ContactForce {
  Vec4 force;
  Vec4 normal;  // the normal part of `force`
  Vec4 c;
};

// v_rel: v_i - v_j (translational); spin: R_i w_i + R_j w_j; u: the stored displacement
// (3 doubles, updated in place; unused without friction); dt_history: the time step, or 0
// for a force evaluation that must not advance the history (the initial one).
template <class Law, bool kFriction, bool kRotation>
[[gnu::always_inline]] inline ContactForce resolve_contact(const Vec4& n, double delta, double d,
                                                           const Vec4& v_rel, const Vec4& spin,
                                                           double m_eff, const LoopMaterial& m,
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
    Vec4 vt = v_rel - vn * n;
    if constexpr (kRotation) vt -= cross(spin, n);
    Vec4 ut = load3(u);
    ut -= ut.dot(n) * n;
    ut += dt_history * vt;
    Vec4 ft = -f * (m.kt * ut + m.gamma_t * m_eff * vt);
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
    out.c = cross(n, ft);
    return out;
  }
}

// The same law for a batch of contacts, one per lane: the pair loop's form. material:
// the lanes' materials; u: the displacements, read and returned updated. Linear contacts
// skip the scale factor f = 1 (multiplying by 1 changes no bit).
struct ContactLanes {
  lanes::Vec force, c;
};
struct MaterialLanes {
  lanes::Reals kn, kt, gamma_n, gamma_t, mu, inv_kt;
};

template <class Law, bool kFriction, bool kRotation>
[[gnu::always_inline]] inline ContactLanes resolve_contacts(
    const lanes::Vec& n, const lanes::Reals& delta, const lanes::Reals& d, const lanes::Vec& v_rel,
    const lanes::Vec& spin, const lanes::Reals& m_eff, const MaterialLanes& m, lanes::Vec& u,
    double dt_history) {
  using lanes::Reals;
  using lanes::Vec;
  constexpr bool kHertz = Law::kind == ContactLaw::Hertz;
  Reals f{};
  if constexpr (kHertz) f = lanes::sqrt(delta / d);
  const Reals vn = dot(v_rel, n);
  Reals fn = m.kn * delta - m.gamma_n * m_eff * vn;
  if constexpr (kHertz) fn = f * fn;
  ContactLanes out;
  const Vec normal = fn * n;
  if constexpr (!kFriction) {
    out.force = normal;
    return out;
  } else {
    Vec vt = v_rel - vn * n;
    if constexpr (kRotation) vt = vt - cross(spin, n);
    const Reals dt = lanes::splat(dt_history);
    Vec ut = u - dot(u, n) * n;
    ut = ut + dt * vt;
    const Reals damping = m.gamma_t * m_eff;
    Vec ft = -(m.kt * ut + damping * vt);
    if constexpr (kHertz) ft = f * ft;
    const Reals limit = m.mu * lanes::abs(fn);
    const Reals ft2 = dot(ft, ft);
    const auto sliding = ft2 > limit * limit;
    // Computed in every lane (a square root and a division per batch, not per contact),
    // kept only where the contact slides.
    const Vec capped = (limit / lanes::sqrt(ft2)) * ft;
    Vec spring = capped;
    if constexpr (kHertz) spring = {capped.x / f, capped.y / f, capped.z / f};
    u = select(sliding, -(m.inv_kt * (spring + damping * vt)), ut);
    ft = select(sliding, capped, ft);
    out.force = normal + ft;
    out.c = cross(n, ft);
    return out;
  }
}

}  // namespace granpipe::dem
