#pragma once
// The padded 3-vectors of the scalar force paths (walls): (x, y, z, 0). With AVX a 4-vector
// is one register, so each vector operation is one instruction, where a 3-vector takes a
// pair, a scalar and the shuffles between them; the zero keeps dot products and norms those
// of the 3-vector.
#include <Eigen/Core>
#include <Eigen/Geometry>

#ifdef __AVX__
#include <immintrin.h>
#endif

namespace granpipe::dem {

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;

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

}  // namespace granpipe::dem
