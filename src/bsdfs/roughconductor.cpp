/*! plugin bsdf roughconductor
Rough metal: microfacet reflection with the conductor's Fresnel term. One-sided.
Mitsuba 3: the same parameters, defaults and named materials; five of them (Ag, Al, Au, Cr, Cu) from other published tables.
uses: microfacet, conductor
| parameter | type | default | meaning | Mitsuba 3 |
| specular_reflectance | spectrum or texture | 1 | a factor on the reflection | same |
*/
#include "bsdfs/roughconductor.h"

#include "bsdfs/bsdf_parameters.h"
#include "optics/conductor_fresnel.h"

namespace columba {

RoughConductorBSDF::RoughConductorBSDF(MicrofacetRoughness roughness, std::optional<ConductorIndexParameter> ior,
                                       SpectrumParameter specularReflectance)
    : roughness_(std::move(roughness)), ior_(std::move(ior)), specularReflectance_(std::move(specularReflectance)) {}

Spectrum RoughConductorBSDF::reflectance(const TexturePoint& p, float cosI, const Wavelengths& wl) const {
  return conductorReflectance(ior_, specularReflectance_.eval(p, wl), cosI, p, wl);
}

Spectrum RoughConductorBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return Spectrum(0.0f);
  const MicrofacetDistribution distribution = roughness_.at(ctx.point);
  Vec3 m = normalize(wi + wo);
  float value = distribution.D(m) * distribution.G(wi, wo, m) / (4.0f * cosTheta(wi));
  if (value <= 0.0f) return Spectrum(0.0f);
  return reflectance(ctx.point, dot(wi, m), wl) * value;
}

float RoughConductorBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return 0.0f;
  const MicrofacetDistribution distribution = roughness_.at(ctx.point);
  Vec3 m = normalize(wi + wo);
  // Visible-normal density times the Jacobian of reflection, dm/dwo = 1 / (4 wo.m).
  return distribution.visiblePdf(wi, m) / (4.0f * dot(wo, m));
}

std::optional<BSDFSample> RoughConductorBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                     float, Vec2 u) const {
  if (cosTheta(wi) <= 0.0f) return std::nullopt;
  const MicrofacetDistribution distribution = roughness_.at(ctx.point);
  Vec3 m = distribution.sampleVisible(wi, u);
  BSDFSample s;
  s.wo = reflect(wi, m);
  if (cosTheta(s.wo) <= 0.0f) return std::nullopt;
  s.pdf = distribution.visiblePdf(wi, m) / (4.0f * dot(s.wo, m));
  if (!(s.pdf > 0.0f)) return std::nullopt;
  // f cos(wo) / pdf: D, G1(wi) and the Jacobian cancel, leaving the masking of wo.
  s.weight = reflectance(ctx.point, dot(wi, m), wl) * distribution.G1(s.wo, m);
  return s;
}

std::shared_ptr<Object> makeRoughConductorBSDF(const Properties& props) {
  MicrofacetRoughness roughness = readMicrofacetRoughness(props, /*allowAnisotropic=*/true);
  std::optional<ConductorIndexParameter> ior = readConductorIndex(props);
  return std::make_shared<RoughConductorBSDF>(
      std::move(roughness), std::move(ior),
      readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance));
}

}  // namespace columba
