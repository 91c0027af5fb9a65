#include "bsdfs/principled_terms.h"

#include <algorithm>
#include <cmath>
#include "core/math.h"

namespace columba {

float schlickWeight(float cosTheta) {
  float m = clampf(1.0f - cosTheta, 0.0f, 1.0f);
  return sqr(sqr(m)) * m;
}

float schlickFresnelWeight(float cosI, float eta) {
  if (eta >= 1.0f) return schlickWeight(cosI);
  float cosT2 = 1.0f - (1.0f - cosI * cosI) / (eta * eta);
  return schlickWeight(safeSqrt(cosT2));
}

float normalIncidenceReflectance(float eta) { return sqr((eta - 1.0f) / (eta + 1.0f)); }

Spectrum tintColour(const Spectrum& base, float baseLuminance) {
  return baseLuminance > 0.0f ? base / baseLuminance : Spectrum(1.0f);
}

MicrofacetDistribution principledDistribution(float roughness, float anisotropic) {
  float alpha = sqr(roughness), aspect = std::sqrt(1.0f - 0.9f * anisotropic);
  return MicrofacetDistribution(MicrofacetType::GGX, std::max(0.001f, alpha / aspect),
                                std::max(0.001f, alpha * aspect));
}

GTR1Distribution GTR1Distribution::fromGloss(float gloss) { return GTR1Distribution(lerp(gloss, 0.1f, 0.001f)); }

float GTR1Distribution::D(const Vec3& m) const {
  if (m.z <= 0.0f) return 0.0f;
  float alpha2 = sqr(alpha_);
  return (alpha2 - 1.0f) / (kPi * std::log(alpha2) * (1.0f + (alpha2 - 1.0f) * sqr(m.z)));
}

Vec3 GTR1Distribution::sample(Vec2 u) const {
  // Inverse of the CDF of cos^2 theta_m under D(m) cos(theta_m).
  float alpha2 = sqr(alpha_);
  float cos2 = clampf((1.0f - std::pow(alpha2, 1.0f - u.y)) / (1.0f - alpha2), 0.0f, 1.0f);
  float cosTheta = std::sqrt(cos2), sinTheta = std::sqrt(1.0f - cos2), phi = kTwoPi * u.x;
  return Vec3(std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta);
}

float GTR1Distribution::pdf(const Vec3& m) const { return D(m) * std::max(m.z, 0.0f); }

float clearcoatShadowing(const Vec3& wi, const Vec3& wo, const Vec3& m) {
  static const MicrofacetDistribution kCoat(MicrofacetType::GGX, 0.25f, 0.25f);
  return kCoat.G(wi, wo, m);
}

float principledDiffuse(float cosI, float cosO, float cosD, float roughness, float flatness) {
  float fi = schlickWeight(cosI), fo = schlickWeight(cosO);
  float lambert = (1.0f - 0.5f * fi) * (1.0f - 0.5f * fo);
  float retroReflection = 2.0f * roughness * sqr(cosD);
  float retro = retroReflection * (fo + fi + fo * fi * (retroReflection - 1.0f));
  // Burley 2012's subsurface approximation: a Lommel-Seeliger-like term, flattened at grazing
  // angles by roughness.
  float fss90 = 0.5f * retroReflection;
  float fss = lerp(fo, 1.0f, fss90) * lerp(fi, 1.0f, fss90);
  float subsurface = 1.25f * (fss * (1.0f / (cosO + cosI) - 0.5f) + 0.5f);
  return lerp(flatness, lambert + retro, subsurface);
}

}  // namespace columba
