#pragma once
// Eight pixels of a span at a time with AVX2, bit for bit the scalar shading (RowShader,
// flat_span): each lane does the scalar operations in their order and precision (double multiply
// then add, rounded to float, float multiply; no fused multiply-add, which would round once
// instead of twice). max(c, 0) then min(, 1) is unit_to_byte's clamp, NaN and -0 included (MAXPS
// returns its second operand for NaN and for two zeros). Shared by the frame buffer's span loop
// (raster/zbuffer.cpp) and the active z-buffer's appended pixels (raster/active_pixels.cpp).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define ZC_HAVE_AVX2_LANES 1
#include <immintrin.h>

namespace zc::avx2 {

// Whether this CPU runs AVX2 (the lanes' callers fall back to their scalar loops otherwise).
inline bool available() {
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

// The columns x .. x+3 and x+4 .. x+7 as doubles.
struct Columns {
  __m256d a, b;
};
__attribute__((target("avx2"))) inline Columns columns8(int x) {
  const __m256d a = _mm256_add_pd(_mm256_set1_pd(double(x)), _mm256_setr_pd(0, 1, 2, 3));
  return {a, _mm256_add_pd(a, _mm256_set1_pd(4.0))};
}

// A plane a0 + ax * x at eight columns, rounded to float.
__attribute__((target("avx2"))) inline __m256 plane8(double a0, __m256d ax, Columns x) {
  const __m256d a = _mm256_set1_pd(a0);
  const __m128 lo = _mm256_cvtpd_ps(_mm256_add_pd(a, _mm256_mul_pd(ax, x.a)));
  const __m128 hi = _mm256_cvtpd_ps(_mm256_add_pd(a, _mm256_mul_pd(ax, x.b)));
  return _mm256_insertf128_ps(_mm256_castps128_ps256(lo), hi, 1);
}

// A colour channel in [0, 1] (clamped) as bytes 0..255, each in its 32-bit lane.
__attribute__((target("avx2"))) inline __m256i to_bytes8(__m256 c) {
  const __m256 v = _mm256_min_ps(_mm256_max_ps(c, _mm256_setzero_ps()), _mm256_set1_ps(1.f));
  return _mm256_cvttps_epi32(
      _mm256_add_ps(_mm256_mul_ps(v, _mm256_set1_ps(255.f)), _mm256_set1_ps(0.5f)));
}

} // namespace zc::avx2
#endif
