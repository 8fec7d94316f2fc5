#pragma once
// Lanes: as many doubles as one vector register holds (8 with AVX-512, 4 with AVX2, 2
// otherwise), as GCC/Clang vector extensions, so that the pair loop's arithmetic is
// written once for every instruction set; gathers and square roots use the set's own
// instructions. Every lane computes exactly what a scalar would (no operation mixes
// lanes), so a pair's result does not depend on which lane or batch it is in.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#if defined(__AVX2__) || defined(__SSE2__)
#include <immintrin.h>
#endif

namespace granpipe::dem::lanes {

#if defined(__AVX512F__)
inline constexpr int kWidth = 8;
#elif defined(__AVX2__)
inline constexpr int kWidth = 4;
#else
inline constexpr int kWidth = 2;
#endif

using Reals = double __attribute__((vector_size(8 * kWidth)));
using Indices = std::int32_t __attribute__((vector_size(4 * kWidth)));

inline Reals splat(double x) { return Reals{} + x; }

inline Reals load(const double* p) {
  Reals v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline Indices load(const std::int32_t* p) {
  Indices v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline void store(double* p, const Reals& v) { std::memcpy(p, &v, sizeof v); }

// base[index[l]] in lane l. (The masked gathers, from zeros: the plain ones start from an
// undefined register, which GCC then warns about.)
inline Reals gather(const double* base, const Indices& index) {
#if defined(__AVX512F__)
  return _mm512_mask_i32gather_pd(_mm512_setzero_pd(), 0xff, reinterpret_cast<__m256i>(index), base,
                                  8);
#elif defined(__AVX2__)
  return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), base, reinterpret_cast<__m128i>(index),
                                  _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
#else
  Reals v;
  for (int l = 0; l < kWidth; ++l) v[l] = base[index[l]];
  return v;
#endif
}

inline Indices gather(const std::int32_t* base, const Indices& index) {
#if defined(__AVX512F__)
  return reinterpret_cast<Indices>(_mm256_mask_i32gather_epi32(
      _mm256_setzero_si256(), base, reinterpret_cast<__m256i>(index), _mm256_set1_epi32(-1), 4));
#elif defined(__AVX2__)
  return reinterpret_cast<Indices>(_mm_mask_i32gather_epi32(
      _mm_setzero_si128(), base, reinterpret_cast<__m128i>(index), _mm_set1_epi32(-1), 4));
#else
  Indices v;
  for (int l = 0; l < kWidth; ++l) v[l] = base[index[l]];
  return v;
#endif
}

inline Reals sqrt(const Reals& x) {
#if defined(__AVX512F__)
  return _mm512_mask_sqrt_pd(_mm512_setzero_pd(), 0xff, x);
#elif defined(__AVX2__)
  return _mm256_sqrt_pd(x);
#elif defined(__SSE2__)
  return _mm_sqrt_pd(x);
#else
  Reals v;
  for (int l = 0; l < kWidth; ++l) v[l] = std::sqrt(x[l]);
  return v;
#endif
}

inline Reals abs(const Reals& x) { return x < 0.0 ? -x : x; }
inline Reals min(const Reals& a, const Reals& b) { return a < b ? a : b; }
inline Reals max(const Reals& a, const Reals& b) { return a > b ? a : b; }
// The largest lane.
inline double max_of(const Reals& x) {
  double m = x[0];
  for (int l = 1; l < kWidth; ++l) m = x[l] > m ? x[l] : m;
  return m;
}

// A 3-vector per lane.
struct Vec {
  Reals x, y, z;
};

inline Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec operator-(const Vec& a) { return {-a.x, -a.y, -a.z}; }
inline Vec operator*(const Reals& s, const Vec& a) { return {s * a.x, s * a.y, s * a.z}; }
inline Reals dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec cross(const Vec& a, const Vec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec select(const decltype(Reals{} < Reals{}) & mask, const Vec& a, const Vec& b) {
  return {mask ? a.x : b.x, mask ? a.y : b.y, mask ? a.z : b.z};
}

// The 3-vectors at base + 3 index[l] (an array of 3 x N doubles), index: kWidth indices.
// With AVX-512 and AVX2, a masked load of (x, y, z) per lane and a transpose: cheaper than
// three gathers, which fetch one double at a time.
inline Vec gather3(const double* base, const std::int32_t* index) {
#if defined(__AVX512F__)
  const auto pair_of = [&](int l) {
    return _mm512_mask_broadcast_f64x4(
        _mm512_maskz_loadu_pd(0x7, base + 3 * std::ptrdiff_t{index[l]}), 0xf0,
        _mm256_maskz_loadu_pd(0x7, base + 3 * std::ptrdiff_t{index[l + 1]}));
  };
  // a..d: lanes (0, 1), (2, 3), (4, 5), (6, 7), each x y z 0 x y z 0.
  const __m512d a = pair_of(0), b = pair_of(2), c = pair_of(4), d = pair_of(6);
  const __m512i xy = _mm512_set_epi64(13, 9, 5, 1, 12, 8, 4, 0);
  const __m512i zw = _mm512_set_epi64(15, 11, 7, 3, 14, 10, 6, 2);
  // ab_xy: x0 x1 x2 x3 y0 y1 y2 y3; ab_z: z0 z1 z2 z3 (and zeros).
  const __m512d ab_xy = _mm512_permutex2var_pd(a, xy, b), cd_xy = _mm512_permutex2var_pd(c, xy, d);
  const __m512d ab_z = _mm512_permutex2var_pd(a, zw, b), cd_z = _mm512_permutex2var_pd(c, zw, d);
  const __m512i low = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
  const __m512i high = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
  return {_mm512_permutex2var_pd(ab_xy, low, cd_xy), _mm512_permutex2var_pd(ab_xy, high, cd_xy),
          _mm512_permutex2var_pd(ab_z, low, cd_z)};
#elif defined(__AVX2__)
  const __m256i xyz = _mm256_setr_epi64x(-1, -1, -1, 0);
  const auto lane = [&](int l) {
    return _mm256_maskload_pd(base + 3 * std::ptrdiff_t{index[l]}, xyz);
  };
  // a..d: lanes 0..3, each x y z 0; ab_xz: x0 x1 z0 z1, ab_y: y0 y1 0 0 (cd_ likewise).
  const __m256d a = lane(0), b = lane(1), c = lane(2), d = lane(3);
  const __m256d ab_xz = _mm256_unpacklo_pd(a, b), ab_y = _mm256_unpackhi_pd(a, b);
  const __m256d cd_xz = _mm256_unpacklo_pd(c, d), cd_y = _mm256_unpackhi_pd(c, d);
  return {_mm256_permute2f128_pd(ab_xz, cd_xz, 0x20), _mm256_permute2f128_pd(ab_y, cd_y, 0x20),
          _mm256_permute2f128_pd(ab_xz, cd_xz, 0x31)};
#else
  const Indices i3 = load(index) * 3;
  return {gather(base, i3), gather(base + 1, i3), gather(base + 2, i3)};
#endif
}

}  // namespace granpipe::dem::lanes
