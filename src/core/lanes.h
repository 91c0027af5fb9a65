#pragma once
// Four floats in one SIMD register (GCC/Clang vector extension): arithmetic evaluated at several
// points at once (a path's wavelengths, a quadrature's nodes) that must not depend on the
// compiler choosing to vectorise a loop.
#include <cmath>
#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace columba {

using FloatLanes = float __attribute__((vector_size(16)));
inline constexpr int kLaneCount = 4;

inline FloatLanes sqrtLanes(FloatLanes v) {
#if defined(__SSE__)
  return _mm_sqrt_ps(v);
#else
  return FloatLanes{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}

inline FloatLanes absLanes(FloatLanes v) { return v < 0.0f ? -v : v; }
inline FloatLanes clampLanes(FloatLanes v, float lo, float hi) {
  v = v < lo ? lo + FloatLanes{} : v;
  return v > hi ? hi + FloatLanes{} : v;
}

// asin per lane for |x| <= 1 (clamped): pi/2 - sqrt(1 - |x|) P(|x|) with the degree-7 polynomial of
// Abramowitz and Stegun 4.4.46 (error < 2e-8 before rounding), then the sign of x.
inline FloatLanes asinLanes(FloatLanes x) {
  FloatLanes a = clampLanes(absLanes(x), 0.0f, 1.0f), a2 = a * a, a4 = a2 * a2;
  FloatLanes p = (1.5707963050f - 0.2145988016f * a) + a2 * (0.0889789874f - 0.0501743046f * a) +
                 a4 * ((0.0308918810f - 0.0170881256f * a) + a2 * (0.0066700901f - 0.0012624911f * a));
  FloatLanes magnitude = 1.5707963268f - sqrtLanes(1.0f - a) * p;
  return x < 0.0f ? -magnitude : magnitude;
}

// {sum of a's lanes, sum of b's, sum of c's, sum of d's}.
inline FloatLanes laneSums(FloatLanes a, FloatLanes b, FloatLanes c, FloatLanes d) {
#if defined(__SSE__)
  // Pairwise: (a0 + a2, b0 + b2, a1 + a3, b1 + b3), the same for c and d, then the halves.
  __m128 ab = _mm_add_ps(_mm_unpacklo_ps(a, b), _mm_unpackhi_ps(a, b));
  __m128 cd = _mm_add_ps(_mm_unpacklo_ps(c, d), _mm_unpackhi_ps(c, d));
  return _mm_add_ps(_mm_movelh_ps(ab, cd), _mm_movehl_ps(cd, ab));
#else
  auto sum = [](FloatLanes v) { return (v[0] + v[2]) + (v[1] + v[3]); };
  return FloatLanes{sum(a), sum(b), sum(c), sum(d)};
#endif
}

}  // namespace columba
