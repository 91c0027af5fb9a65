#pragma once
// Scalar helpers shared by every module.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace columba {

inline constexpr double kPiDouble = 3.14159265358979323846;
inline constexpr float kPi = float(kPiDouble);
inline constexpr float kInvPi = 1.0f / kPi;
inline constexpr float kTwoPi = 2.0f * kPi;
inline constexpr float kHalfPi = 0.5f * kPi;
// The largest float below 1: samples must stay in [0, 1).
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

template <typename T>
constexpr T sqr(T x) {
  return x * x;
}
// x limited to [lo, hi]; NaN gives lo, so that an index computed from a clamped value is always
// one (a NaN sample or wavelength made int(NaN) index tables out of bounds).
inline float clampf(float x, float lo, float hi) { return std::isnan(x) ? lo : std::min(std::max(x, lo), hi); }
inline float lerp(float t, float a, float b) { return a + t * (b - a); }
inline float safeSqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }
inline double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }
inline float safeAsin(float x) { return std::asin(clampf(x, -1.0f, 1.0f)); }
inline float safeAcos(float x) { return std::acos(clampf(x, -1.0f, 1.0f)); }
inline float degToRad(float d) { return d * (kPi / 180.0f); }
// The real roots t0 <= t1 of a t^2 + b t + c = 0 (a != 0; false when there are none), without the
// cancellation of the textbook formula: q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, roots q / a, c / q.
inline bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
  double disc = b * b - 4.0 * a * c;
  if (disc < 0.0 || a == 0.0) return false;
  double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  t0 = q / a;
  t1 = q != 0.0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}
inline float radToDeg(float r) { return r * (180.0f / kPi); }

// sqrt, sin and cos for compile-time constants (std::sqrt and std::sin are not constexpr before
// C++26), in double. sqrt: Newton's iteration from above, for 0 < x < 2^64.
constexpr double constexprSqrt(double x) {
  double r = x > 1.0 ? x : 1.0;
  for (int k = 0; k < 64; ++k) r = 0.5 * (r + x / r);
  return r;
}
// sin and cos: their Taylor series, within a few double ulps for |x| <= pi/4.
constexpr double constexprSin(double x) {
  double term = x, sum = x;
  for (int k = 1; k <= 12; ++k) sum += term *= -x * x / ((2 * k) * (2 * k + 1));
  return sum;
}
constexpr double constexprCos(double x) {
  double term = 1.0, sum = 1.0;
  for (int k = 1; k <= 12; ++k) sum += term *= -x * x / ((2 * k - 1) * (2 * k));
  return sum;
}

}  // namespace columba
