/*! plugin bsdf roughdielectric
A rough interface between two dielectrics: microfacet reflection and refraction (Walter et al. 2007), sampled through the normals visible from the incident direction, then reflection with the Fresnel reflectance at that normal as its probability. Refraction scales radiance by (η_i/η_t)², as `dielectric` does.
Mitsuba 3: the same parameters and defaults; the roughness may be a texture.
uses: microfacet
| parameter | type | default | meaning | Mitsuba 3 |
| int_ior | float or string | `bk7` (1.5046) | the index inside: a positive number or a named material | same |
| ext_ior | float or string | `air` (1.000277) | the index outside | same |
| specular_reflectance | spectrum or texture | 1 | a factor on the reflection | same |
| specular_transmittance | spectrum or texture | 1 | a factor on the transmission | same |
*/
#include "bsdfs/roughdielectric.h"

#include "bsdfs/bsdf_parameters.h"
#include "bsdfs/microfacet_interface.h"
#include "optics/fresnel.h"

namespace columba {

namespace {
// The Fresnel factor of the component the pair belongs to.
float componentFresnel(const InterfacePair& p, float fresnel) { return p.reflection ? fresnel : 1.0f - fresnel; }
}  // namespace

RoughDielectricBSDF::RoughDielectricBSDF(MicrofacetRoughness roughness, float eta,
                                         SpectrumParameter specularReflectance, SpectrumParameter specularTransmittance)
    : roughness_(std::move(roughness)),
      eta_(eta),
      specularReflectance_(std::move(specularReflectance)),
      specularTransmittance_(std::move(specularTransmittance)) {}

Spectrum RoughDielectricBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo,
                                   const Wavelengths& wl) const {
  InterfacePair p = interfacePair(wi, wo, eta_);
  if (!p.valid) return Spectrum(0.0f);
  float f = componentFresnel(p, fresnelDielectric(dot(p.wi, p.m), p.eta)) * interfaceValue(roughness_.at(ctx.point), p);
  return (p.reflection ? specularReflectance_ : specularTransmittance_).eval(ctx.point, wl) * f;
}

float RoughDielectricBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  InterfacePair p = interfacePair(wi, wo, eta_);
  if (!p.valid) return 0.0f;
  return componentFresnel(p, fresnelDielectric(dot(p.wi, p.m), p.eta)) * interfaceDensity(roughness_.at(ctx.point), p);
}

std::optional<BSDFSample> RoughDielectricBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                      float uComponent, Vec2 u) const {
  if (cosTheta(wi) == 0.0f) return std::nullopt;
  bool inside = cosTheta(wi) < 0.0f;
  Vec3 front = inside ? mirroredThroughSurface(wi) : wi;
  float eta = inside ? 1.0f / eta_ : eta_;
  const MicrofacetDistribution distribution = roughness_.at(ctx.point);
  Vec3 m = distribution.sampleVisible(front, u);
  float cosI = dot(front, m);
  if (!(cosI > 0.0f)) return std::nullopt;
  FresnelAmplitudes a = fresnelAmplitudes(cosI, eta);
  float fresnel = 0.5f * (a.rs * a.rs + a.rp * a.rp);
  bool reflection = uComponent < fresnel;
  Vec3 wo = reflection ? reflect(front, m) : refractThrough(front, m, cosI, eta, a.cosT);
  // A reflection below the surface or a refraction back above it is light the microfacets'
  // neighbours would stop (and no other half vector could give it): no sample.
  if (reflection != (wo.z > 0.0f)) return std::nullopt;
  if (inside) wo = mirroredThroughSurface(wo);
  InterfacePair p = interfacePair(wi, wo, eta_);
  if (!p.valid) return std::nullopt;
  // The Fresnel factor at the half vector pdf() sees.
  float chosen = componentFresnel(p, fresnelDielectric(dot(p.wi, p.m), p.eta));
  BSDFSample s;
  s.wo = wo;
  s.pdf = chosen * interfaceDensity(distribution, p);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = (p.reflection ? specularReflectance_ : specularTransmittance_).eval(ctx.point, wl) *
             (chosen * interfaceValue(distribution, p) / s.pdf);
  return s;
}

std::shared_ptr<Object> makeRoughDielectricBSDF(const Properties& props) {
  MicrofacetRoughness roughness = readMicrofacetRoughness(props, /*allowAnisotropic=*/true);
  float intIOR = readIOR(props, "int_ior", "bk7");
  float extIOR = readIOR(props, "ext_ior", "air");
  return std::make_shared<RoughDielectricBSDF>(
      std::move(roughness), intIOR / extIOR,
      readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance),
      readSpectrumParameter(props, "specular_transmittance", 1.0f, SpectrumUse::Reflectance));
}

}  // namespace columba
