#pragma once
// Scalar helpers shared by every module.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace columba {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kTwoPi = 2.0f * kPi;
inline constexpr float kHalfPi = 0.5f * kPi;

template <typename T> constexpr T sqr(T x) { return x * x; }
inline float clampf(float x, float lo, float hi) { return std::min(std::max(x, lo), hi); }
inline float lerp(float t, float a, float b) { return a + t * (b - a); }
inline float safeSqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }
inline double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }
inline float safeAsin(float x) { return std::asin(clampf(x, -1.0f, 1.0f)); }
inline float safeAcos(float x) { return std::acos(clampf(x, -1.0f, 1.0f)); }
inline float degToRad(float d) { return d * (kPi / 180.0f); }
inline float radToDeg(float r) { return r * (180.0f / kPi); }

// sin and cos of |x| <= pi/2 by their Taylor polynomials of degree 11 and 12 (errors < 6e-8):
// cheaper than the library's full-range functions. T is float or a SIMD vector of floats.
template <typename T> inline void sinCosWithinQuarterTurn(T x, T& sinX, T& cosX) {
  T x2 = x * x;
  T s = T{} + -1.0f / 39916800;  // -1/11!
  for (float c : {1.0f / 362880, -1.0f / 5040, 1.0f / 120, -1.0f / 6, 1.0f}) s = s * x2 + c;
  T k = T{} + 1.0f / 479001600;  // 1/12!
  for (float c : {-1.0f / 3628800, 1.0f / 40320, -1.0f / 720, 1.0f / 24, -0.5f, 1.0f}) k = k * x2 + c;
  sinX = x * s;
  cosX = k;
}

}  // namespace columba
