#pragma once
// Scalar helpers shared by every module.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace columba {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kTwoPi = 2.0f * kPi;
inline constexpr float kHalfPi = 0.5f * kPi;
// The largest float below 1: samples must stay in [0, 1).
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

template <typename T> constexpr T sqr(T x) { return x * x; }
inline float clampf(float x, float lo, float hi) { return std::min(std::max(x, lo), hi); }
inline float lerp(float t, float a, float b) { return a + t * (b - a); }
inline float safeSqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }
inline double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }
inline float safeAsin(float x) { return std::asin(clampf(x, -1.0f, 1.0f)); }
inline float safeAcos(float x) { return std::acos(clampf(x, -1.0f, 1.0f)); }
inline float degToRad(float d) { return d * (kPi / 180.0f); }
inline float radToDeg(float r) { return r * (180.0f / kPi); }

// sin(x) / x and cos(x) for |x| <= pi/2 by their Taylor polynomials of degree 10 and 12 (truncation
// errors < 6e-8, about two float ulps with rounding): cheaper than the library's full-range
// functions. T is float or a SIMD vector of floats. The polynomials are evaluated in Estrin's
// form, whose dependency chains are half as long as Horner's.
template <typename T> inline void sincAndCosWithinQuarterTurn(T x, T& sinOverX, T& cosX) {
  T z = x * x, z2 = z * z, z4 = z2 * z2;
  // sin(x) / x = sum of (-z)^k / (2k + 1)!, k = 0..5; cos(x) = sum of (-z)^k / (2k)!, k = 0..6.
  T s01 = 1.0f - z * (1.0f / 6), s23 = 1.0f / 120 - z * (1.0f / 5040), s45 = 1.0f / 362880 - z * (1.0f / 39916800);
  T c01 = 1.0f - z * 0.5f, c23 = 1.0f / 24 - z * (1.0f / 720), c45 = 1.0f / 40320 - z * (1.0f / 3628800);
  sinOverX = s01 + z2 * s23 + z4 * s45;
  cosX = c01 + z2 * c23 + z4 * (c45 + z2 * (1.0f / 479001600));
}
template <typename T> inline void sinCosWithinQuarterTurn(T x, T& sinX, T& cosX) {
  T sinOverX;
  sincAndCosWithinQuarterTurn(x, sinOverX, cosX);
  sinX = x * sinOverX;
}

// Inverse error function for |x| < 1 in single precision (M. Giles, "Approximating the erfinv
// function", GPU Computing Gems, 2011): polynomials in w = -log(1 - x^2), one for the body and one
// in sqrt(w) for the far tails; relative error about 1e-7.
inline float erfInverse(float x) {
  float w = -std::log((1.0f - x) * (1.0f + x)), p;
  if (w < 5.0f) {
    w -= 2.5f;
    p = 2.81022636e-08f;
    p = 3.43273939e-07f + p * w;
    p = -3.5233877e-06f + p * w;
    p = -4.39150654e-06f + p * w;
    p = 0.00021858087f + p * w;
    p = -0.00125372503f + p * w;
    p = -0.00417768164f + p * w;
    p = 0.246640727f + p * w;
    p = 1.50140941f + p * w;
  } else {
    w = std::sqrt(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w;
    p = 0.00134934322f + p * w;
    p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;
    p = -0.0076224613f + p * w;
    p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;
    p = 2.83297682f + p * w;
  }
  return p * x;
}

}  // namespace columba
