#include "kernels.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "walls.hpp"

namespace granpipe::dem {

namespace {

inline Vec3 load(const double* a, std::ptrdiff_t i) {
  return Vec3(a[3 * i], a[3 * i + 1], a[3 * i + 2]);
}
inline Vec4 load4(const double* a, std::ptrdiff_t i) { return load3(a + 3 * i); }
template <class V>
inline void store(double* a, std::ptrdiff_t i, const V& v) {
  a[3 * i] = v[0];
  a[3 * i + 1] = v[1];
  a[3 * i + 2] = v[2];
}
inline void store_zero(double* a, std::ptrdiff_t i) { a[3 * i] = a[3 * i + 1] = a[3 * i + 2] = 0.0; }

// Reaction slot per pair: the force on the partner, and n x F_t when spins matter.
template <bool kRotation>
constexpr int kStride = kRotation ? 6 : 3;

// A wall slot particle i does not touch: its history and recorded forces are zero.
template <bool kFriction>
[[gnu::always_inline]] inline void clear_wall_contact(const ForceContext& c, int slot, int i) {
  if constexpr (kFriction) store_zero(c.wall_history[slot], i);
  if (c.wall_normal_record) {
    store_zero(c.wall_normal_record[slot], i);
    store_zero(c.wall_tangential_record[slot], i);
  }
}

// Adds particle i's wall forces to f and its wall contacts' n x F_t to spin_sum. Most
// particles touch no wall, so everything a contact needs (the mass, the material, the
// normal) is made only once the overlap says it touches.
template <class Law, bool kFriction, bool kRotation>
[[gnu::always_inline]] inline void add_wall_forces(const ForceContext& c, int i, const Vec4& xi,
                                                   const Vec4& vi, const Vec4& wi, Vec4& f,
                                                   Vec4& spin_sum) {
  const double ai = c.radius[i];
  const Vec4 wall_velocity = load3(c.wall_velocity.data());
  const auto touch = [&](int slot, const Vec4& n, double delta) __attribute__((always_inline)) {
    double* u = kFriction ? c.wall_history[slot] + 3 * static_cast<std::ptrdiff_t>(i) : nullptr;
    const Vec4 spin = kRotation ? Vec4(ai * wi) : Vec4::Zero();
    const LoopMaterial& material = c.wall_material[slot * c.species_count + c.species[i]];
    const ContactForce cf = resolve_contact<Law, kFriction, kRotation>(
        n, delta, 2.0 * ai, vi - wall_velocity, spin, 1.0 / c.inv_mass[i], material, u,
        c.dt_history);
    f += cf.force;
    if constexpr (kRotation) spin_sum += cf.c;
    if (c.wall_normal_record) {
      store(c.wall_normal_record[slot], i, cf.normal);
      store(c.wall_tangential_record[slot], i, cf.force - cf.normal);
    }
  };
  for (int s = 0; s < c.planes; ++s) {
    const int axis = c.plane_axis[s];
    const double sign = c.plane_sign[s];
    const double delta = plane_overlap(sign, xi[axis], c.plane_position[s], ai);
    if (delta <= 0.0) {
      clear_wall_contact<kFriction>(c, s, i);
      continue;
    }
    Vec4 n = Vec4::Zero();
    n[axis] = sign;
    touch(s, n, delta);
  }
  if (c.cylinder) {
    const double dx = xi[0] - c.cylinder_x, dy = xi[1] - c.cylinder_y;
    double rho = 0.0;
    const double delta = cylinder_overlap(dx, dy, c.cylinder_radius, ai, rho);
    if (delta <= 0.0) {
      clear_wall_contact<kFriction>(c, c.planes, i);
    } else {
      touch(c.planes, Vec4(-dx / rho, -dy / rho, 0.0, 0.0), delta);
    }
  }
}

// The pair loop takes a particle's pairs in blocks of this many, in two passes each.
constexpr int kBlock = 32;

// The pairs of one block that touch, in list order, with what the first pass computed.
struct TouchingPairs {
  int count = 0;
  std::int32_t pair[kBlock];
  Vec4 d[kBlock];  // x_i - x_j
  double r2[kBlock];
};

// The first pass over pairs [k0, k1) of particle i: lists the touching pairs, clears every
// reaction slot (those of touching pairs are written again) and the history of the pairs
// out of contact. Without branches: whether a listed pair touches is close to a coin toss
// (about half of them do), which a branch per pair would often mispredict.
template <bool kFriction, int kStride>
[[gnu::always_inline]] inline void find_touching(const ForceContext& c, const Vec4& xi, double ai,
                                                 std::int32_t k0, std::int32_t k1,
                                                 TouchingPairs& t) {
  t.count = 0;
  for (std::int32_t k = k0; k < k1; ++k) {
    const std::int32_t j = c.partner[k];
    const Vec4 d = xi - load4(c.x, j);
    const double r2 = d.squaredNorm(), contact = ai + c.radius[j];
    const bool touching = !(r2 >= contact * contact);
    t.pair[t.count] = k;
    t.d[t.count] = d;
    t.r2[t.count] = r2;
    t.count += touching;
    std::fill_n(c.reaction + static_cast<std::ptrdiff_t>(kStride) * k, kStride, 0.0);
    if constexpr (kFriction) {
      // u & keep, not a select, which the compiler makes a branch.
      double* u = c.history + 3 * static_cast<std::ptrdiff_t>(k);
      const std::uint64_t keep = -static_cast<std::uint64_t>(touching);
      for (int a = 0; a < 3; ++a) {
        u[a] = std::bit_cast<double>(std::bit_cast<std::uint64_t>(u[a]) & keep);
      }
    }
  }
}

template <class Law, bool kFriction, bool kRotation>
void forces(const ForceContext& c) {
  constexpr int stride = kStride<kRotation>;
  const int S = c.species_count;
#pragma omp parallel for schedule(static) num_threads(c.threads)
  for (int i = 0; i < c.n; ++i) {
    const Vec4 xi = load4(c.x, i), vi = load4(c.v, i);
    const Vec4 wi = kRotation ? load4(c.omega, i) : Vec4::Zero();
    const double ai = c.radius[i], inv_mi = c.inv_mass[i];
    const LoopMaterial* row = c.pair_material + c.species[i] * S;
    const Vec4 wall_velocity = load3(c.wall_velocity.data());
    Vec4 fi = -c.background_damping * vi - c.air_damping * (vi - wall_velocity);
    Vec4 ci = Vec4::Zero();
    TouchingPairs touching;
    for (std::int32_t k0 = c.first[i]; k0 < c.first[i + 1]; k0 += kBlock) {
      find_touching<kFriction, stride>(c, xi, ai, k0, std::min(k0 + kBlock, c.first[i + 1]),
                                       touching);
      // The second pass: the touching pairs' forces, in list order.
      for (int t = 0; t < touching.count; ++t) {
        const std::int32_t k = touching.pair[t], j = c.partner[k];
        double* rk = c.reaction + static_cast<std::ptrdiff_t>(stride) * k;
        double* u = kFriction ? c.history + 3 * static_cast<std::ptrdiff_t>(k) : nullptr;
        const double aj = c.radius[j], contact = ai + aj, r = std::sqrt(touching.r2[t]);
        const Vec4 n = touching.d[t] / r;
        const Vec4 spin = kRotation ? Vec4(ai * wi + aj * load4(c.omega, j)) : Vec4::Zero();
        const ContactForce cf = resolve_contact<Law, kFriction, kRotation>(
            n, contact - r, contact, vi - load4(c.v, j), spin, 1.0 / (inv_mi + c.inv_mass[j]),
            row[c.species[j]], u, c.dt_history);
        fi += cf.force;
        rk[0] = -cf.force[0];
        rk[1] = -cf.force[1];
        rk[2] = -cf.force[2];
        if constexpr (kRotation) {
          ci += cf.c;
          rk[3] = cf.c[0];
          rk[4] = cf.c[1];
          rk[5] = cf.c[2];
        }
      }
    }
    add_wall_forces<Law, kFriction, kRotation>(c, i, xi, vi, wi, fi, ci);
    store(c.force, i, fi);
    if constexpr (kRotation) store(c.spin_sum, i, ci);
  }
}

// The end of a step for particle p: its reactions gathered, then v += dt/2 a (and the
// spin likewise).
template <bool kRotation>
[[gnu::always_inline]] inline void finish(const KickContext& c, int p) {
  constexpr int stride = kStride<kRotation>;
  const double h = 0.5 * c.dt;
  Vec3 f = load(c.force, p);
  Vec3 spin = kRotation ? load(c.spin_sum, p) : Vec3::Zero();
  for (std::int32_t m = c.reverse_first[p]; m < c.reverse_first[p + 1]; ++m) {
    const double* rk = c.reaction + static_cast<std::ptrdiff_t>(stride) * c.reverse_pair[m];
    f += Vec3(rk[0], rk[1], rk[2]);
    if constexpr (kRotation) spin += Vec3(rk[3], rk[4], rk[5]);
  }
  store(c.force, p, f);
  store(c.v, p, load(c.v, p) + h * (c.inv_mass[p] * f + c.gravity));
  if constexpr (kRotation) {
    const Vec3 torque = -c.radius[p] * spin;
    store(c.torque, p, torque);
    store(c.omega, p, load(c.omega, p) + (h * c.inv_inertia[p]) * torque);
  }
}

// The start of a step for particle p: v += dt/2 a, x += dt v (and the spin's half kick);
// returns its squared displacement since the last list build.
template <bool kRotation>
[[gnu::always_inline]] inline double start(const KickContext& c, int p) {
  const double h = 0.5 * c.dt;
  const Vec3 v = load(c.v, p) + h * (c.inv_mass[p] * load(c.force, p) + c.gravity);
  const Vec3 x = load(c.x, p) + c.dt * v;
  store(c.v, p, v);
  store(c.x, p, x);
  if constexpr (kRotation) {
    store(c.omega, p, load(c.omega, p) + (h * c.inv_inertia[p]) * load(c.torque, p));
  }
  return (x - load(c.x_build, p)).squaredNorm();
}

template <bool kRotation>
void finish_step(const KickContext& c) {
#pragma omp parallel for schedule(static) num_threads(c.threads)
  for (int p = 0; p < c.n; ++p) finish<kRotation>(c, p);
}

template <bool kRotation>
double start_step(const KickContext& c) {
  double worst = 0.0;
#pragma omp parallel for schedule(static) num_threads(c.threads) reduction(max : worst)
  for (int p = 0; p < c.n; ++p) worst = std::max(worst, start<kRotation>(c, p));
  return worst;
}

// The two above in one pass: the same arithmetic, one sweep over memory and one barrier
// fewer per step.
template <bool kRotation>
double finish_and_start(const KickContext& c) {
  double worst = 0.0;
#pragma omp parallel for schedule(static) num_threads(c.threads) reduction(max : worst)
  for (int p = 0; p < c.n; ++p) {
    finish<kRotation>(c, p);
    worst = std::max(worst, start<kRotation>(c, p));
  }
  return worst;
}

template <class Law, bool kFriction, bool kRotation>
Kernels kernels_of() {
  return {&forces<Law, kFriction, kRotation>, &finish_step<kRotation>, &start_step<kRotation>,
          &finish_and_start<kRotation>, kStride<kRotation>};
}

template <class Law>
Kernels kernels_of_law(bool friction, bool rotation) {
  if (!friction) return kernels_of<Law, false, false>();
  return rotation ? kernels_of<Law, true, true>() : kernels_of<Law, true, false>();
}

}  // namespace

Kernels select_kernels(ContactLaw law, bool friction, bool rotation) {
  return law == ContactLaw::Linear ? kernels_of_law<LinearLaw>(friction, rotation)
                                   : kernels_of_law<HertzLaw>(friction, rotation);
}

}  // namespace granpipe::dem
