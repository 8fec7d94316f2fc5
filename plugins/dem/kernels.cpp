#include "kernels.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include "contact_evaluator.hpp"
#include "lanes.hpp"
#include "walls.hpp"

namespace granpipe::dem {

namespace {

inline Vec4 load4(const double* a, std::ptrdiff_t i) { return load3(a + 3 * i); }
inline void store(double* a, std::ptrdiff_t i, const Vec4& v) { store3(a + 3 * i, v); }
inline void store_zero(double* a, std::ptrdiff_t i) {
  a[3 * i] = a[3 * i + 1] = a[3 * i + 2] = 0.0;
}

// Reaction slot per pair: the force on the partner, and n x F_t when spins matter.
template <bool kRotation>
constexpr int kStride = kRotation ? 6 : 3;

// A wall slot particle i does not touch: its histories and recorded forces are zero.
template <class C>
[[gnu::always_inline]] inline void clear_wall_contact(const ForceContext& c, int slot, int i) {
  if constexpr (C::kFriction) store_zero(c.wall_history[slot], i);
  if constexpr (C::kRolling) store_zero(c.wall_rolling_history[slot], i);
  if (c.wall_normal_record) {
    store_zero(c.wall_normal_record[slot], i);
    store_zero(c.wall_tangential_record[slot], i);
  }
}

// Adds particle i's wall forces to f and its wall contacts' n x F_t to spin_sum. Most
// particles touch no wall, so everything a contact needs (the mass, the material, the
// normal) is made only once the overlap says it touches.
// beyond: the running maximum of overlap - overlap_limit x radius.
template <class C>
[[gnu::always_inline]] inline void add_wall_forces(const ForceContext& c, int i, const Vec4& xi,
                                                   const Vec4& vi, const Vec4& wi, Vec4& f,
                                                   Vec4& spin_sum, double& beyond) {
  const double ai = c.radius[i];
  const Vec4 wall_velocity = load3(c.wall_velocity.data());
  const auto touch = [&](int slot, const Vec4& n, double delta) __attribute__((always_inline)) {
    beyond = std::max(beyond, delta - c.overlap_limit * ai);
    const std::ptrdiff_t at = 3 * static_cast<std::ptrdiff_t>(i);
    ContactHistory<ScalarMath> h;
    if constexpr (C::kFriction) h.u = load3(c.wall_history[slot] + at);
    if constexpr (C::kRolling) h.theta = load3(c.wall_rolling_history[slot] + at);
    ContactInput<ScalarMath> in;
    in.n = n;
    in.delta = delta;
    in.d = 2.0 * ai;
    in.v_rel = vi - wall_velocity;
    in.spin = C::kSpin ? Vec4(ai * wi) : Vec4::Zero();
    in.m_eff = 1.0 / c.inv_mass[i];
    if constexpr (C::kRolling) {
      in.w_rel = wi;
      in.r_eff = ai;
    }
    const LoopMaterial& material = c.wall_material[slot * c.species_count + c.species[i]];
    const ContactResult<ScalarMath> cf =
        C::template evaluate<ScalarMath>(in, material, h, c.dt_history);
    if constexpr (C::kFriction) store3(c.wall_history[slot] + at, h.u);
    if constexpr (C::kRolling) store3(c.wall_rolling_history[slot] + at, h.theta);
    f += cf.force;
    // The torque on i is -a_i times the spin sum (finish_step).
    if constexpr (C::kSpin) spin_sum += cf.c;
    if constexpr (C::kRolling) spin_sum -= cf.roll / ai;
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
      clear_wall_contact<C>(c, s, i);
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
      clear_wall_contact<C>(c, c.planes, i);
    } else {
      touch(c.planes, Vec4(-dx / rho, -dy / rho, 0.0, 0.0), delta);
    }
  }
}

// The pair loop works through a thread's pairs in blocks of this many listed pairs.
constexpr int kBlock = 128;
static_assert(kBlock % 8 == 0, "the AVX-512 first pass takes whole batches of 8 before the last");
constexpr int kPadded = kBlock + lanes::kWidth;

// The pairs of one block that touch, in list order, structure of arrays padded to whole
// batches of lanes: what the first pass found, then what the second computed.
struct TouchingPairs {
  int count = 0;
  std::int32_t pair[kPadded], i[kPadded], j[kPadded];
  double dx[kPadded], dy[kPadded], dz[kPadded], r2[kPadded];
  double fx[kPadded], fy[kPadded], fz[kPadded];  // force on i
  double cx[kPadded], cy[kPadded], cz[kPadded];  // i's spin sum: n x F_t (- roll / a_i)
  double px[kPadded], py[kPadded], pz[kPadded];  // with rolling, the partner's: c + roll / a_j
  double ux[kPadded], uy[kPadded], uz[kPadded];  // the updated histories
  double rx[kPadded], ry[kPadded], rz[kPadded];
};

#if defined(__AVX512F__)
// Zeroes the 3-vectors of a history (3 doubles per pair) of the pairs k .. k+7 that the
// mask leaves out. Bit a of pair l's three doubles is bit 3 l + a of the store mask.
inline void clear_history(double* history, std::int32_t k, __mmask8 cleared) {
  const unsigned clear = _pdep_u32(cleared, 0x249249u) * 7u;
  double* u = history + 3 * static_cast<std::ptrdiff_t>(k);
  const __m512d zero = _mm512_setzero_pd();
  _mm512_mask_storeu_pd(u, static_cast<__mmask8>(clear), zero);
  _mm512_mask_storeu_pd(u + 8, static_cast<__mmask8>(clear >> 8), zero);
  _mm512_mask_storeu_pd(u + 16, static_cast<__mmask8>(clear >> 16), zero);
}
#else
// Keeps pair k's history (3 doubles) where keep is all ones, zeroes it where it is zero:
// u & keep, not a select, which the compiler makes a branch.
inline void keep_history(double* history, std::int32_t k, std::uint64_t keep) {
  double* u = history + 3 * static_cast<std::ptrdiff_t>(k);
  for (int a = 0; a < 3; ++a) {
    u[a] = std::bit_cast<double>(std::bit_cast<std::uint64_t>(u[a]) & keep);
  }
}
#endif

// Lists the pairs of [k0, k1) that touch into t (from entry 0), clears the history of the
// others and returns how many touch. Without branches: whether a listed pair touches is
// close to a coin toss (about half of them do), which a branch per pair would often
// mispredict.
template <class C>
[[gnu::always_inline]] inline int list_touching(const ForceContext& c, std::int32_t k0,
                                                std::int32_t k1, TouchingPairs& t) {
#if defined(__AVX512F__)
  // Eight pairs at a time: their touching lanes compressed within registers, stored whole
  // (what lies past the count is overwritten next), and the history of the others cleared
  // by masked stores. (Compressing straight to memory is slow on AMD's cores.)
  int count = 0;
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  alignas(32) std::int32_t i[8], j[8];
  for (std::int32_t k = k0; k < k1; k += 8) {
    const __mmask8 valid = k1 - k >= 8 ? 0xff : static_cast<__mmask8>((1u << (k1 - k)) - 1);
    const __m256i vi = _mm256_maskz_loadu_epi32(valid, c.owner + k);
    const __m256i vj = _mm256_maskz_loadu_epi32(valid, c.partner + k);
    _mm256_store_si256(reinterpret_cast<__m256i*>(i), vi);
    _mm256_store_si256(reinterpret_cast<__m256i*>(j), vj);
    const lanes::Vec d = lanes::gather3(c.x, i) - lanes::gather3(c.x, j);
    const lanes::Reals r2 = dot(d, d);
    const lanes::Reals contact = lanes::gather(c.radius, reinterpret_cast<lanes::Indices>(vi)) +
                                 lanes::gather(c.radius, reinterpret_cast<lanes::Indices>(vj));
    const __mmask8 touching = _mm512_mask_cmp_pd_mask(valid, r2, contact * contact, _CMP_NGE_UQ);
    const auto put = [&](double* to, const lanes::Reals& v) {
      _mm512_storeu_pd(to + count, _mm512_maskz_compress_pd(touching, v));
    };
    const auto put_index = [&](std::int32_t* to, __m256i v) {
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(to + count),
                          _mm256_maskz_compress_epi32(touching, v));
    };
    put_index(t.pair, _mm256_add_epi32(_mm256_set1_epi32(k), lane));
    put_index(t.i, vi);
    put_index(t.j, vj);
    put(t.dx, d.x);
    put(t.dy, d.y);
    put(t.dz, d.z);
    put(t.r2, r2);
    count += std::popcount(static_cast<unsigned>(touching));
    if constexpr (C::kFriction) clear_history(c.history, k, valid & ~touching);
    if constexpr (C::kRolling) clear_history(c.rolling_history, k, valid & ~touching);
  }
  return count;
#else
  int count = 0;
  for (std::int32_t k = k0; k < k1; ++k) {
    const std::int32_t i = c.owner[k], j = c.partner[k];
    const double* xi = c.x + 3 * static_cast<std::ptrdiff_t>(i);
    const double* xj = c.x + 3 * static_cast<std::ptrdiff_t>(j);
    const double dx = xi[0] - xj[0], dy = xi[1] - xj[1], dz = xi[2] - xj[2];
    const double r2 = dx * dx + dy * dy + dz * dz, contact = c.radius[i] + c.radius[j];
    const bool touching = !(r2 >= contact * contact);
    t.pair[count] = k;
    t.i[count] = i;
    t.j[count] = j;
    t.dx[count] = dx;
    t.dy[count] = dy;
    t.dz[count] = dz;
    t.r2[count] = r2;
    count += touching;
    [[maybe_unused]] const std::uint64_t keep = -static_cast<std::uint64_t>(touching);
    if constexpr (C::kFriction) keep_history(c.history, k, keep);
    if constexpr (C::kRolling) keep_history(c.rolling_history, k, keep);
  }
  return count;
#endif
}

// The first pass over pairs [k0, k1): lists the touching pairs and clears the history of
// the pairs out of contact. The list is padded with copies of its last pair to a whole
// batch of lanes.
template <class C>
[[gnu::always_inline]] inline void find_touching(const ForceContext& c, std::int32_t k0,
                                                 std::int32_t k1, TouchingPairs& t) {
  const int count = list_touching<C>(c, k0, k1, t);
  t.count = count;
  for (int e = count; count > 0 && e % lanes::kWidth != 0; ++e) {
    t.pair[e] = t.pair[count - 1];
    t.i[e] = t.i[count - 1];
    t.j[e] = t.j[count - 1];
    t.dx[e] = t.dx[count - 1];
    t.dy[e] = t.dy[count - 1];
    t.dz[e] = t.dz[count - 1];
    t.r2[e] = t.r2[count - 1];
  }
}

// The pair materials as the pair loop reads them. With AVX-512 (AVX2) and at most 8 (4)
// species pairs, each field is a register of the table's column, read by a lane
// permutation (one instruction where a gather takes a load per lane).
struct PairMaterials {
  static constexpr int kFields = kMaterialFields;
  // Species pairs whose fields fit one register, read by a lane permutation.
  static constexpr int kColumnRows = lanes::kWidth;
  const double* table;  // species x species LoopMaterials, kFields doubles each
  int species;
#if defined(__AVX512F__)
  __m512d column[kFields];
#elif defined(__AVX2__)
  __m256d column[kFields];
#endif

  explicit PairMaterials(const ForceContext& c)
      : table(reinterpret_cast<const double*>(c.pair_material)), species(c.species_count) {
    static_assert(sizeof(LoopMaterial) == kFields * sizeof(double));
#if defined(__AVX512F__) || defined(__AVX2__)
    if (species * species > kColumnRows) return;
    for (int f = 0; f < kFields; ++f) {
      alignas(64) double v[kColumnRows] = {};
      for (int r = 0; r < species * species; ++r) v[r] = table[kFields * r + f];
      std::memcpy(&column[f], v, sizeof column[f]);
    }
#endif
  }

  // The first `fields` fields of the lanes' materials (the others zero): a loop without
  // rolling resistance reads no rolling field.
  template <int kRead, class Field>
  static MaterialOf<lanes::Reals> fields(const Field& field) {
    MaterialOf<lanes::Reals> m{};
    m.kn = field(0);
    m.kt = field(1);
    m.gamma_n = field(2);
    m.gamma_t = field(3);
    m.mu = field(4);
    m.inv_kt = field(5);
    if constexpr (kRead > kMaterialFieldsWithoutRolling) {
      m.mu_roll = field(6);
      m.k_roll = field(7);
    }
    return m;
  }

  // The materials of the lanes' pairs (i, j).
  template <int kRead>
  MaterialOf<lanes::Reals> of(const ForceContext& c, const lanes::Indices& i,
                              const lanes::Indices& j) const {
    if (species == 1) return fields<kRead>([&](int f) { return lanes::splat(table[f]); });
    const lanes::Indices row = lanes::gather(c.species, i) * species + lanes::gather(c.species, j);
#if defined(__AVX512F__)
    if (species * species <= kColumnRows) {
      // (The masked forms: the plain ones start from an undefined register, which GCC
      // warns about.)
      const __m512i r = _mm512_maskz_cvtepi32_epi64(0xff, reinterpret_cast<__m256i>(row));
      return fields<kRead>(
          [&](int f) { return lanes::Reals(_mm512_maskz_permutexvar_pd(0xff, r, column[f])); });
    }
#elif defined(__AVX2__)
    if (species * species <= kColumnRows) {
      // Row r's double is the column's 32-bit halves 2r (low) and 2r + 1 (high).
      const __m256i r = _mm256_cvtepi32_epi64(reinterpret_cast<__m128i>(row));
      const __m256i halves =
          _mm256_add_epi64(_mm256_add_epi64(_mm256_slli_epi64(r, 1), _mm256_slli_epi64(r, 33)),
                           _mm256_set1_epi64x(std::int64_t{1} << 32));
      return fields<kRead>([&](int f) {
        return lanes::Reals(
            _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(column[f]), halves)));
      });
    }
#endif
    const lanes::Indices at = row * kFields;
    return fields<kRead>([&](int f) { return lanes::gather(table + f, at); });
  }
};

// The second pass: the touching pairs' forces, a batch of lanes at a time. beyond: the
// running maximum, per lane, of overlap - overlap_limit x the smaller radius (the padding
// repeats a listed pair, so it adds nothing).
inline void store(double* x, double* y, double* z, int b, const lanes::Vec& v) {
  lanes::store(x + b, v.x);
  lanes::store(y + b, v.y);
  lanes::store(z + b, v.z);
}

template <class C>
[[gnu::always_inline]] inline void resolve_touching(const ForceContext& c,
                                                    const PairMaterials& materials,
                                                    TouchingPairs& t, lanes::Reals& beyond) {
  using lanes::Indices;
  using lanes::load;
  using lanes::Reals;
  using lanes::Vec;
  for (int b = 0; b < t.count; b += lanes::kWidth) {
    const Indices i = load(t.i + b), j = load(t.j + b);
    const Reals ai = lanes::gather(c.radius, i), aj = lanes::gather(c.radius, j);
    const Reals r = lanes::sqrt(load(t.r2 + b)), contact = ai + aj;
    beyond = lanes::max(beyond, (contact - r) - c.overlap_limit * lanes::min(ai, aj));
    ContactInput<LaneMath> in;
    // One division, not three (divisions are the slowest lane operations).
    in.n = (1.0 / r) * Vec{load(t.dx + b), load(t.dy + b), load(t.dz + b)};
    in.delta = contact - r;
    in.d = contact;
    in.v_rel = lanes::gather3(c.v, t.i + b) - lanes::gather3(c.v, t.j + b);
    in.spin = Vec{};
    if constexpr (C::kSpin) {
      const Vec wi = lanes::gather3(c.omega, t.i + b), wj = lanes::gather3(c.omega, t.j + b);
      in.spin = ai * wi + aj * wj;
      if constexpr (C::kRolling) {
        in.w_rel = wi - wj;
        in.r_eff = ai * aj / contact;
      }
    }
    in.m_eff = 1.0 / (lanes::gather(c.inv_mass, i) + lanes::gather(c.inv_mass, j));
    ContactHistory<LaneMath> h{};
    if constexpr (C::kFriction) h.u = lanes::gather3(c.history, t.pair + b);
    if constexpr (C::kRolling) h.theta = lanes::gather3(c.rolling_history, t.pair + b);
    const ContactResult<LaneMath> cf = C::template evaluate<LaneMath>(
        in, materials.of<C::kFields>(c, i, j), h, lanes::splat(c.dt_history));
    store(t.fx, t.fy, t.fz, b, cf.force);
    if constexpr (C::kRolling) {
      // The rolling torque enters the spin sums, which finish_step turns into -a times them.
      store(t.cx, t.cy, t.cz, b, cf.c - (1.0 / ai) * cf.roll);
      store(t.px, t.py, t.pz, b, cf.c + (1.0 / aj) * cf.roll);
    } else if constexpr (C::kSpin) {
      store(t.cx, t.cy, t.cz, b, cf.c);
    }
    if constexpr (C::kFriction) store(t.ux, t.uy, t.uz, b, h.u);
    if constexpr (C::kRolling) store(t.rx, t.ry, t.rz, b, h.theta);
  }
}

// The touching pairs' results written out in list order: reaction slot, history, and the
// owner's sums.
template <class C>
[[gnu::always_inline]] inline void write_touching(const ForceContext& c, const TouchingPairs& t) {
  constexpr int stride = kStride<C::kSpin>;
  for (int e = 0; e < t.count; ++e) {
    const std::ptrdiff_t k = t.pair[e], i = t.i[e];
    double* rk = c.incoming + stride * std::ptrdiff_t{c.reaction_slot[k]};
    double* fi = c.force + 3 * i;
    rk[0] = -t.fx[e];
    rk[1] = -t.fy[e];
    rk[2] = -t.fz[e];
    fi[0] += t.fx[e];
    fi[1] += t.fy[e];
    fi[2] += t.fz[e];
    if constexpr (C::kSpin) {
      double* ci = c.spin_sum + 3 * i;
      const bool own = !C::kRolling;  // the partner's spin sum is the owner's, unless rolling
      rk[3] = own ? t.cx[e] : t.px[e];
      rk[4] = own ? t.cy[e] : t.py[e];
      rk[5] = own ? t.cz[e] : t.pz[e];
      ci[0] += t.cx[e];
      ci[1] += t.cy[e];
      ci[2] += t.cz[e];
    }
    if constexpr (C::kFriction) {
      double* u = c.history + 3 * k;
      u[0] = t.ux[e];
      u[1] = t.uy[e];
      u[2] = t.uz[e];
    }
    if constexpr (C::kRolling) {
      double* theta = c.rolling_history + 3 * k;
      theta[0] = t.rx[e];
      theta[1] = t.ry[e];
      theta[2] = t.rz[e];
    }
  }
}

// Particle i's own forces: background and air damping, then its walls (beyond: as in
// add_wall_forces).
template <class C>
[[gnu::always_inline]] inline void own_forces(const ForceContext& c, int i, double& beyond) {
  const Vec4 xi = load4(c.x, i), vi = load4(c.v, i);
  const Vec4 wi = C::kSpin ? load4(c.omega, i) : Vec4::Zero();
  const Vec4 wall_velocity = load3(c.wall_velocity.data());
  Vec4 fi = -c.background_damping * vi - c.air_damping * (vi - wall_velocity);
  Vec4 ci = Vec4::Zero();
  add_wall_forces<C>(c, i, xi, vi, wi, fi, ci, beyond);
  store(c.force, i, fi);
  if constexpr (C::kSpin) store(c.spin_sum, i, ci);
}

// Where thread `part`'s particles start: the first particle past its share of the
// estimated work (see NeighborList::work_before).
inline int share_start(const ForceContext& c, int part) {
  if (part == 0) return 0;
  if (part == c.threads) return c.n;
  const double share = c.work_before[c.n] * part / c.threads;
  return static_cast<int>(std::lower_bound(c.work_before, c.work_before + c.n, share) -
                          c.work_before);
}

// Each thread takes one contiguous block of particles, of about equal work: their own
// forces first, then the pairs they own, which add to them in list order. A particle's sum
// is thus the same for any split. (By particle count, the denser bottom of the Brazil-nut
// bed gave the first of two threads 11 % more work than the second.)
// (Each thread works on its own copy of the context: the vector stores may alias
// anything whose address is known elsewhere, which would make every access to a field a
// reload.)
// The deepest contact's overlap beyond the limit is a maximum over threads, which does not
// depend on the split.
template <class C>
double forces(const ForceContext& context) {
  const ForceContext c = context;
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  double deepest = kNone;
#pragma omp parallel for schedule(static, 1) num_threads(c.threads) firstprivate(c) \
    reduction(max                                                                   \
              : deepest)
  for (int part = 0; part < c.threads; ++part) {
    const int p0 = share_start(c, part), p1 = share_start(c, part + 1);
    double walls = kNone;
    for (int i = p0; i < p1; ++i) own_forces<C>(c, i, walls);
    TouchingPairs touching;
    const PairMaterials materials(c);
    lanes::Reals pairs = lanes::splat(kNone);
    for (std::int32_t k0 = c.first[p0]; k0 < c.first[p1]; k0 += kBlock) {
      find_touching<C>(c, k0, std::min(k0 + kBlock, c.first[p1]), touching);
      resolve_touching<C>(c, materials, touching, pairs);
      write_touching<C>(c, touching);
    }
    deepest = std::max({deepest, walls, lanes::max_of(pairs)});
  }
  return deepest;
}

// Particle p's force and spin sum with its reactions gathered (in pair order), their
// slots cleared for the next force pass, which writes only the touching pairs' slots.
template <bool kRotation>
[[gnu::always_inline]] inline Vec4 gathered_force(const KickContext& c, int p, Vec4& spin) {
  constexpr std::ptrdiff_t stride = kStride<kRotation>;
  Vec4 f = load4(c.force, p);
  spin = kRotation ? load4(c.spin_sum, p) : Vec4::Zero();
  double* begin = c.incoming + stride * c.reverse_first[p];
  double* const end = c.incoming + stride * c.reverse_first[p + 1];
  for (double* rk = begin; rk != end; rk += stride) {
    f += load3(rk);
    if constexpr (kRotation) spin += load3(rk + 3);
    // Cleared slot by slot: a call to memset per particle costs more.
    if (!c.keep_reactions)
      for (int a = 0; a < stride; ++a) rk[a] = 0.0;
  }
  return f;
}

// The changes of a half kick, dt/2 a and dt/2 alpha.
struct HalfKick {
  Vec4 dv, dw;
};
template <bool kRotation>
[[gnu::always_inline]] inline HalfKick half_kick(const KickContext& c, int p, const Vec4& f,
                                                 const Vec4& torque) {
  const double h = 0.5 * c.dt;
  HalfKick k;
  k.dv = h * (c.inv_mass[p] * f + load3(c.gravity.data()));
  if constexpr (kRotation) k.dw = (h * c.inv_inertia[p]) * torque;
  return k;
}

// The end of a step for particle p: its reactions gathered, then v += dt/2 a (and the
// spin likewise).
template <bool kRotation>
[[gnu::always_inline]] inline void finish(const KickContext& c, int p) {
  Vec4 spin;
  const Vec4 f = gathered_force<kRotation>(c, p, spin);
  const Vec4 torque = kRotation ? Vec4(-c.radius[p] * spin) : Vec4::Zero();
  store(c.force, p, f);
  const HalfKick k = half_kick<kRotation>(c, p, f, torque);
  store(c.v, p, load4(c.v, p) + k.dv);
  if constexpr (kRotation) {
    store(c.torque, p, torque);
    store(c.omega, p, load4(c.omega, p) + k.dw);
  }
}

// The drift: x += dt v; returns the squared displacement since the last list build.
[[gnu::always_inline]] inline double drift(const KickContext& c, int p, const Vec4& v) {
  const Vec4 x = load4(c.x, p) + c.dt * v;
  store(c.x, p, x);
  return (x - load4(c.x_build, p)).squaredNorm();
}

// The start of a step for particle p: v += dt/2 a, x += dt v (and the spin's half kick);
// returns its squared displacement since the last list build.
template <bool kRotation>
[[gnu::always_inline]] inline double start(const KickContext& c, int p) {
  const HalfKick k =
      half_kick<kRotation>(c, p, load4(c.force, p), kRotation ? load4(c.torque, p) : Vec4::Zero());
  const Vec4 v = load4(c.v, p) + k.dv;
  store(c.v, p, v);
  if constexpr (kRotation) store(c.omega, p, load4(c.omega, p) + k.dw);
  return drift(c, p, v);
}

template <bool kRotation>
void finish_step(const KickContext& context) {
  const KickContext c = context;
#pragma omp parallel for schedule(static) num_threads(c.threads) firstprivate(c)
  for (int p = 0; p < c.n; ++p) finish<kRotation>(c, p);
}

template <bool kRotation>
double start_step(const KickContext& context) {
  const KickContext c = context;
  double worst = 0.0;
#pragma omp parallel for schedule(static) num_threads(c.threads) firstprivate(c) \
    reduction(max                                                                \
              : worst)
  for (int p = 0; p < c.n; ++p) worst = std::max(worst, start<kRotation>(c, p));
  return worst;
}

// The two above in one pass: the same arithmetic, one sweep over memory and one barrier
// fewer per step.
template <bool kRotation>
double finish_and_start(const KickContext& context) {
  const KickContext c = context;
  double worst = 0.0;
#pragma omp parallel for schedule(static) num_threads(c.threads) firstprivate(c) \
    reduction(max                                                                \
              : worst)
  for (int p = 0; p < c.n; ++p) {
    // finish then start, the second kick reusing the first's increments.
    Vec4 spin;
    const Vec4 f = gathered_force<kRotation>(c, p, spin);
    const Vec4 torque = kRotation ? Vec4(-c.radius[p] * spin) : Vec4::Zero();
    const HalfKick k = half_kick<kRotation>(c, p, f, torque);
    const Vec4 v = load4(c.v, p) + k.dv + k.dv;
    store(c.v, p, v);
    if constexpr (kRotation) store(c.omega, p, load4(c.omega, p) + k.dw + k.dw);
    worst = std::max(worst, drift(c, p, v));
  }
  return worst;
}

template <class C>
Kernels kernels_of() {
  return {&forces<C>, &finish_step<C::kSpin>, &start_step<C::kSpin>, &finish_and_start<C::kSpin>,
          kStride<C::kSpin>};
}

}  // namespace

// This copy's entry point (kernels.hpp), in the namespace of the instruction set it is
// compiled for.
#if defined(__AVX512F__)
namespace avx512 {
#elif defined(__AVX2__)
namespace avx2 {
#else
namespace baseline {
#endif

Kernels select_kernels(ContactLaw law, bool friction, bool rotation, bool rolling) {
  return with_contact(law, friction, rotation, rolling,
                      [](auto contact) { return kernels_of<decltype(contact)>(); });
}

}  // namespace avx512, avx2 or baseline

}  // namespace granpipe::dem
