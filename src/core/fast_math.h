#pragma once
// SIMD lanes and fast maths, in one place: the four- and eight-float register types with their
// helpers, and the approximations that stand in for library functions in inner loops (the barbule
// BSDF's quadrature, the thin film, sampling). Each approximation states its domain and error;
// tests/core/test_fast_math.cpp checks them against the standard library over the whole domain.
//
// Lanes use the GCC/Clang vector extension: arithmetic evaluated at several points at once (a
// path's wavelengths, a quadrature's nodes) that must not depend on the compiler choosing to
// vectorise a loop.
#include <immintrin.h>
#include <cmath>
#include <type_traits>
#include <vector>
#include "core/math.h"

namespace columba {

// ---- Lane types

using FloatLanes = float __attribute__((vector_size(16)));
inline constexpr int kLaneCount = 4;
// Eight lanes, for functions compiled for AVX2 (__attribute__((target("avx2,fma")))); the helpers
// below that take them are inlined into such functions.
using FloatLanes8 = float __attribute__((vector_size(32)));

// Four 2D vectors, one per lane.
struct Vec2Lanes {
  FloatLanes x, y;
};

// ---- Lane helpers

inline FloatLanes sqrtLanes(FloatLanes v) {
#if defined(__SSE__)
  return _mm_sqrt_ps(v);
#else
  return FloatLanes{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}
__attribute__((target("avx2,fma"), always_inline)) inline FloatLanes8 sqrtLanes(FloatLanes8 v) {
  return FloatLanes8(_mm256_sqrt_ps(__m256(v)));
}

inline FloatLanes absLanes(FloatLanes v) { return v < 0.0f ? -v : v; }
inline FloatLanes clampLanes(FloatLanes v, float lo, float hi) {
  v = v < lo ? lo + FloatLanes{} : v;
  return v > hi ? hi + FloatLanes{} : v;
}

// {sum of a's lanes, sum of b's, sum of c's, sum of d's}, each as (v0 + v2) + (v1 + v3).
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

// Whether this processor runs the eight-lane code (AVX2 with FMA), for callers that dispatch on it.
inline bool hasAvx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  return avx2;
}

// Eight lanes as two halves of four, and back.
__attribute__((target("avx2,fma"), always_inline)) inline FloatLanes8 joinLanes(FloatLanes low, FloatLanes high) {
  return FloatLanes8{low[0], low[1], low[2], low[3], high[0], high[1], high[2], high[3]};
}
__attribute__((target("avx2,fma"), always_inline)) inline FloatLanes lowLanes(FloatLanes8 v) {
  return FloatLanes{v[0], v[1], v[2], v[3]};
}
__attribute__((target("avx2,fma"), always_inline)) inline FloatLanes highLanes(FloatLanes8 v) {
  return FloatLanes{v[4], v[5], v[6], v[7]};
}

// `values` in groups of kLaneCount lanes, the last group padded with zeros (a quadrature rule's
// nodes and weights: padding lanes weigh nothing).
inline std::vector<FloatLanes> laneGroups(const std::vector<double>& values) {
  std::vector<FloatLanes> groups((values.size() + kLaneCount - 1) / kLaneCount, FloatLanes{});
  for (size_t k = 0; k < values.size(); ++k) groups[k / kLaneCount][k % kLaneCount] = float(values[k]);
  return groups;
}

// ---- Approximations

// asin per lane on [-1, 1] (clamped beyond): pi/2 - sqrt(1 - |x|) P(|x|) with the degree-7
// polynomial of Abramowitz and Stegun 4.4.46 (error < 2e-8 before rounding), then the sign of x.
inline FloatLanes asinLanes(FloatLanes x) {
  FloatLanes a = clampLanes(absLanes(x), 0.0f, 1.0f), a2 = a * a, a4 = a2 * a2;
  FloatLanes p = (1.5707963050f - 0.2145988016f * a) + a2 * (0.0889789874f - 0.0501743046f * a) +
                 a4 * ((0.0308918810f - 0.0170881256f * a) + a2 * (0.0066700901f - 0.0012624911f * a));
  FloatLanes magnitude = kHalfPi - sqrtLanes(1.0f - a) * p;
  return x < 0.0f ? -magnitude : magnitude;
}

// sin(x) / x and cos(x) for |x| <= pi/2 by their Taylor polynomials of degree 10 and 12 (truncation
// errors < 6e-8, about two float ulps with rounding): cheaper than the library's full-range
// functions. T is float or lanes. The polynomials are evaluated in Estrin's form, whose dependency
// chains are half as long as Horner's.
template <typename T>
inline void sincAndCosWithinQuarterTurn(T x, T& sinOverX, T& cosX) {
  T z = x * x, z2 = z * z, z4 = z2 * z2;
  // sin(x) / x = sum of (-z)^k / (2k + 1)!, k = 0..5; cos(x) = sum of (-z)^k / (2k)!, k = 0..6.
  T s01 = 1.0f - z * (1.0f / 6), s23 = 1.0f / 120 - z * (1.0f / 5040), s45 = 1.0f / 362880 - z * (1.0f / 39916800);
  T c01 = 1.0f - z * 0.5f, c23 = 1.0f / 24 - z * (1.0f / 720), c45 = 1.0f / 40320 - z * (1.0f / 3628800);
  sinOverX = s01 + z2 * s23 + z4 * s45;
  cosX = c01 + z2 * c23 + z4 * (c45 + z2 * (1.0f / 479001600));
}
template <typename T>
inline void sinCosWithinQuarterTurn(T x, T& sinX, T& cosX) {
  T sinOverX;
  sincAndCosWithinQuarterTurn(x, sinOverX, cosX);
  sinX = x * sinOverX;
}

// cos(x) and sin(x) for small angles, |x| <= kSmallAngleLimit (the barbules' longitudinal normal
// angles), by two Taylor terms each: truncation errors below x^4 / 24 < 1.8e-6 and |x|^5 / 120,
// float rounding once |x| < 0.03. T is float or lanes.
inline constexpr float kSmallAngleLimit = 0.08f;
template <typename T>
inline void cosSinOfSmallAngle(T x, T& cosX, T& sinX) {
  T xSqr = x * x;
  cosX = 1.0f - 0.5f * xSqr;
  sinX = x * (1.0f - xSqr * (1.0f / 6.0f));
}

// Adding and subtracting 1.5 * 2^23 rounds a float of magnitude below 2^22 to the nearest integer.
inline constexpr float kRoundToNearest = 1.5f * float(1 << 23);

// The range reduction's constants as full vectors, defined out of line (fast_math.cpp): four-lane
// arithmetic then reads them as memory operands, where a visible constant is re-broadcast from a
// scalar at each use.
struct SinSqrConstants {
  FloatLanes invPi, pi, roundToNearest;
};
extern const SinSqrConstants kSinSqrConstants;

// sin^2(x) for 0 <= x <= kSinSqrLimit (a thin film's half phase; the limit is reached by a film
// 9 um thick at 360 nm): sin^2 has period pi, so x is reduced to [-pi/2, pi/2] by the nearest
// multiple of pi, then sinCosWithinQuarterTurn. The reduction's error grows with x, to about
// 1e-7 x absolute. Lanes is four or eight lanes (always inlined into its caller, whose
// instruction set it then uses).
inline constexpr float kSinSqrLimit = 256.0f;
template <typename Lanes>
__attribute__((always_inline)) inline Lanes sinSqr(Lanes x) {
  Lanes turns, whole, y;
  if constexpr (std::is_same_v<Lanes, FloatLanes>) {
    const SinSqrConstants& k = kSinSqrConstants;
    turns = x * k.invPi;
    whole = (turns + k.roundToNearest) - k.roundToNearest;
    y = (turns - whole) * k.pi;
  } else {
    turns = x * (1.0f / kPi);
    whole = (turns + kRoundToNearest) - kRoundToNearest;
    y = (turns - whole) * kPi;
  }
  Lanes sinOverY, cosY;
  sincAndCosWithinQuarterTurn(y, sinOverY, cosY);
  Lanes sinY = y * sinOverY;
  return sinY * sinY;
}

}  // namespace columba
