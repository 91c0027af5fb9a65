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

template <typename T> constexpr T sqr(T x) { return x * x; }
inline float clampf(float x, float lo, float hi) { return std::min(std::max(x, lo), hi); }
inline float lerp(float t, float a, float b) { return a + t * (b - a); }
inline float safeSqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }
inline double safeSqrt(double x) { return std::sqrt(std::max(x, 0.0)); }
inline float safeAsin(float x) { return std::asin(clampf(x, -1.0f, 1.0f)); }
inline float safeAcos(float x) { return std::acos(clampf(x, -1.0f, 1.0f)); }
inline float degToRad(float d) { return d * (kPi / 180.0f); }
inline float radToDeg(float r) { return r * (180.0f / kPi); }

}  // namespace columba
