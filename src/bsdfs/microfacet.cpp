#include "bsdfs/microfacet.h"

#include <cmath>

namespace columba {

namespace {

constexpr double kInvSqrtPi = 1.0 / constexprSqrt(kPiDouble);

// Slope along the incident azimuth of a normal visible from a direction at polar angle theta,
// for the unit-roughness Beckmann distribution. In slope space the visible density is
// proportional to (cos(theta) - x sin(theta))+ exp(-x^2 - y^2); its x-marginal has the CDF
//   C(x) = cos(theta) (1 + erf x) / 2 + sin(theta) exp(-x^2) / (2 sqrt(pi)),  x <= cot(theta),
// which is inverted here by Newton's method kept inside a shrinking bracket. With theta = 0 this
// is the inverse CDF of the y-marginal, a normal distribution of variance 1/2.
double sampleBeckmannSlope(double cosTheta, double sinTheta, double u) {
  auto cdf = [&](double x) {
    return 0.5 * cosTheta * (1.0 + std::erf(x)) + 0.5 * kInvSqrtPi * sinTheta * std::exp(-x * x);
  };
  // Beyond |x| = 7 the density is below 1e-21 of its peak.
  double lo = -7.0, hi = 7.0;
  if (sinTheta > 0.0) hi = std::min(hi, cosTheta / sinTheta);
  const double target = u * cdf(hi);
  double x = std::clamp(0.0, lo, hi);
  for (int i = 0; i < 64; ++i) {
    double f = cdf(x) - target;
    if (std::abs(f) <= 1e-12 * target || hi - lo < 1e-12) break;
    if (f > 0.0)
      hi = x;
    else
      lo = x;
    double slope = (cosTheta - x * sinTheta) * std::exp(-x * x) * kInvSqrtPi;
    double next = x - f / slope;
    // Bisect where the Newton step leaves the bracket (or the density vanishes).
    x = (slope > 0.0 && next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  return x;
}

}  // namespace

MicrofacetDistribution::MicrofacetDistribution(MicrofacetType type, float alphaX, float alphaY)
    : type_(type), alphaX_(std::max(alphaX, 1e-4f)), alphaY_(std::max(alphaY, 1e-4f)) {}

float MicrofacetDistribution::D(const Vec3& m) const {
  if (m.z <= 0.0f) return 0.0f;
  // Slopes scaled to unit roughness.
  float x = m.x / alphaX_, y = m.y / alphaY_, z2 = m.z * m.z;
  float norm = kPi * alphaX_ * alphaY_;
  if (type_ == MicrofacetType::Beckmann) return std::exp(-(x * x + y * y) / z2) / (norm * z2 * z2);
  return 1.0f / (norm * sqr(x * x + y * y + z2));
}

float MicrofacetDistribution::lambda(const Vec3& w) const {
  // alpha(w) tan(theta), the projected roughness along w's azimuth times the slope of w.
  double alphaTan2 = (sqr(double(alphaX_) * w.x) + sqr(double(alphaY_) * w.y)) / sqr(double(w.z));
  if (type_ == MicrofacetType::GGX) return float(0.5 * (std::sqrt(1.0 + alphaTan2) - 1.0));
  if (alphaTan2 == 0.0) return 0.0f;
  double a = 1.0 / std::sqrt(alphaTan2);
  return float(0.5 * (std::exp(-a * a) * kInvSqrtPi / a - std::erfc(a)));
}

float MicrofacetDistribution::G1(const Vec3& w, const Vec3& m) const {
  if (dot(w, m) * w.z <= 0.0f) return 0.0f;
  return 1.0f / (1.0f + lambda(w));
}

float MicrofacetDistribution::G(const Vec3& wi, const Vec3& wo, const Vec3& m) const { return G1(wi, m) * G1(wo, m); }

Vec3 MicrofacetDistribution::sampleVisible(const Vec3& wi, Vec2 u) const {
  return type_ == MicrofacetType::GGX ? sampleVisibleGGX(wi, u) : sampleVisibleBeckmann(wi, u);
}

float MicrofacetDistribution::visiblePdf(const Vec3& wi, const Vec3& m) const {
  if (wi.z <= 0.0f) return 0.0f;
  return G1(wi, m) * std::max(dot(wi, m), 0.0f) * D(m) / wi.z;
}

// Heitz 2018, "Sampling the GGX Distribution of Visible Normals": in the configuration stretched
// to unit roughness the visible normals are the projection of a uniform disk sample onto the
// hemisphere around the (stretched) incident direction, its far half compressed by the
// hemisphere's foreshortening.
Vec3 MicrofacetDistribution::sampleVisibleGGX(const Vec3& wi, Vec2 u) const {
  Vec3 wh = normalize(Vec3(alphaX_ * wi.x, alphaY_ * wi.y, wi.z));
  float lenSq = wh.x * wh.x + wh.y * wh.y;
  Vec3 t1 = lenSq > 0.0f ? Vec3(-wh.y, wh.x, 0.0f) / std::sqrt(lenSq) : Vec3(1.0f, 0.0f, 0.0f);
  Vec3 t2 = cross(wh, t1);
  float r = std::sqrt(u.x), phi = kTwoPi * u.y;
  float p1 = r * std::cos(phi), p2 = r * std::sin(phi);
  float s = 0.5f * (1.0f + wh.z);
  p2 = (1.0f - s) * safeSqrt(1.0f - p1 * p1) + s * p2;
  Vec3 nh = p1 * t1 + p2 * t2 + safeSqrt(1.0f - p1 * p1 - p2 * p2) * wh;
  return normalize(Vec3(alphaX_ * nh.x, alphaY_ * nh.y, std::max(nh.z, 1e-6f)));
}

// Heitz & d'Eon 2014: stretch to unit roughness, sample the visible slopes for the incident
// polar angle with its azimuth rotated to 0, rotate back and unstretch.
Vec3 MicrofacetDistribution::sampleVisibleBeckmann(const Vec3& wi, Vec2 u) const {
  Vec3 ws = normalize(Vec3(alphaX_ * wi.x, alphaY_ * wi.y, wi.z));
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - sqr(double(ws.z))));
  double cosPhi = 1.0, sinPhi = 0.0;
  if (sinTheta > 1e-7) {
    cosPhi = ws.x / sinTheta;
    sinPhi = ws.y / sinTheta;
  }
  double sx = sampleBeckmannSlope(ws.z, sinTheta, u.x);
  double sy = sampleBeckmannSlope(1.0, 0.0, u.y);
  double slopeX = alphaX_ * (cosPhi * sx - sinPhi * sy);
  double slopeY = alphaY_ * (sinPhi * sx + cosPhi * sy);
  return normalize(Vec3(float(-slopeX), float(-slopeY), 1.0f));
}

}  // namespace columba
