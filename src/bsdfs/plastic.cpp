/*! plugin bsdf plastic
Smooth plastic: a smooth dielectric coat that reflects specularly over an ideal diffuse base. Light refracts into the coat, scatters off the base and leaves after any number of internal reflections at the coat's underside, each with the diffuse Fresnel reflectance. One-sided.
Mitsuba 3: the same parameters and defaults.
| parameter | type | default | meaning | Mitsuba 3 |
| int_ior | float or string | `polypropylene` (1.49) | the coat's index of refraction: a positive number or a named material | same |
| ext_ior | float or string | `air` (1.000277) | the index of the medium outside | same |
| diffuse_reflectance | spectrum or texture | 0.5 | the base's albedo | same |
| specular_reflectance | spectrum or texture | 1 | a factor on the specular reflection | same |
| nonlinear | boolean | false | the base's colour shifts with internal scattering (a darker, more saturated result) | same |
*/
#include "bsdfs/plastic.h"

#include "bsdfs/bsdf_parameters.h"
#include "core/sampling.h"
#include "optics/diffuse_fresnel.h"
#include "optics/fresnel.h"

namespace columba {

PlasticBSDF::PlasticBSDF(float eta, SpectrumParameter diffuseReflectance, SpectrumParameter specularReflectance,
                         bool nonlinear)
    : eta_(eta),
      diffuseReflectance_(std::move(diffuseReflectance)),
      specularReflectance_(std::move(specularReflectance)),
      nonlinear_(nonlinear),
      internalReflectance_(fresnelDiffuseReflectance(1.0f / eta)) {
  float d = diffuseReflectance_.meanValue(), s = specularReflectance_.meanValue();
  specularSamplingWeight_ = d + s > 0.0f ? s / (d + s) : 0.5f;
}

float PlasticBSDF::specularProbability(float fresnelI) const {
  float specular = fresnelI * specularSamplingWeight_;
  float diffuse = (1.0f - fresnelI) * (1.0f - specularSamplingWeight_);
  return specular + diffuse > 0.0f ? specular / (specular + diffuse) : 0.0f;
}

Spectrum PlasticBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return Spectrum(0.0f);
  Spectrum kd = diffuseReflectance_.eval(ctx.point, wl);
  Spectrum base =
      kd / (nonlinear_ ? Spectrum(1.0f) - kd * internalReflectance_ : Spectrum(1.0f - internalReflectance_));
  // 1/eta^2: radiance leaving the coat spreads into the larger solid angle outside.
  float transmission = (1.0f - fresnelDielectric(cosTheta(wi), eta_)) * (1.0f - fresnelDielectric(cosTheta(wo), eta_));
  return base * (transmission / (eta_ * eta_) * kInvPi * cosTheta(wo));
}

float PlasticBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return 0.0f;
  float pSpecular = specularProbability(fresnelDielectric(cosTheta(wi), eta_));
  return (1.0f - pSpecular) * cosineHemispherePdf(cosTheta(wo));
}

std::optional<BSDFSample> PlasticBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                              float uComponent, Vec2 u) const {
  if (cosTheta(wi) <= 0.0f) return std::nullopt;
  float fresnelI = fresnelDielectric(cosTheta(wi), eta_);
  float pSpecular = specularProbability(fresnelI);
  BSDFSample s;
  if (uComponent < pSpecular) {
    s.wo = mirrorDirection(wi);
    s.pdf = pSpecular;
    s.delta = true;
    s.weight = specularReflectance_.eval(ctx.point, wl) * (fresnelI / pSpecular);
    return s;
  }
  s.wo = sampleCosineHemisphere(u);
  s.pdf = (1.0f - pSpecular) * cosineHemispherePdf(cosTheta(s.wo));
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = eval(ctx, wi, s.wo, wl) / s.pdf;
  return s;
}

std::shared_ptr<Object> makePlasticBSDF(const Properties& props) {
  float intIOR = readIOR(props, "int_ior", "polypropylene");
  float extIOR = readIOR(props, "ext_ior", "air");
  return std::make_shared<PlasticBSDF>(
      intIOR / extIOR, readSpectrumParameter(props, "diffuse_reflectance", 0.5f, SpectrumUse::Reflectance),
      readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance),
      props.getBool("nonlinear", false));
}

}  // namespace columba
