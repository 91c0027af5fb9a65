#pragma once
// Warps from the unit square to common domains, each with its density.
#include "core/fast_math.h"
#include "core/vector.h"

namespace columba {

inline Vec2 sampleConcentricDisk(Vec2 u) {
  float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
  if (a == 0.0f && b == 0.0f) return {0, 0};
  // The angle is phi = (pi/4) (b/a), or pi/2 - (pi/4) (a/b), whose cosine and sine swap.
  bool first = std::abs(a) > std::abs(b);
  float r = first ? a : b, x = (kPi / 4.0f) * (first ? b / a : a / b);
  float sinX, cosX;
  sinCosWithinQuarterTurn(x, sinX, cosX);
  return first ? Vec2(r * cosX, r * sinX) : Vec2(r * sinX, r * cosX);
}

inline Vec3 sampleCosineHemisphere(Vec2 u) {
  Vec2 d = sampleConcentricDisk(u);
  float z = safeSqrt(1.0f - d.x * d.x - d.y * d.y);
  return {d.x, d.y, z};
}
inline float cosineHemispherePdf(float cosTheta) { return std::max(cosTheta, 0.0f) * kInvPi; }

inline Vec3 sampleUniformSphere(Vec2 u) {
  float z = 1.0f - 2.0f * u.x;
  float r = safeSqrt(1.0f - z * z);
  float phi = kTwoPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline constexpr float uniformSpherePdf() { return 1.0f / (4.0f * kPi); }

inline Vec3 sampleUniformCone(Vec2 u, float cosMax) {
  float z = 1.0f - u.x * (1.0f - cosMax);
  float r = safeSqrt(1.0f - z * z);
  float phi = kTwoPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline float uniformConePdf(float cosMax) { return 1.0f / (kTwoPi * (1.0f - cosMax)); }

inline Vec2 sampleUniformTriangle(Vec2 u) {
  float su = std::sqrt(u.x);
  return {1.0f - su, u.y * su};
}

// Power heuristic with beta = 2 (Veach 1997).
inline float powerHeuristic(float pdfA, float pdfB) {
  float a = pdfA * pdfA, b = pdfB * pdfB;
  if (std::isinf(a)) return 1.0f;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

}  // namespace columba
