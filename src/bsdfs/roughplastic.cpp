/*! plugin bsdf roughplastic
Rough plastic: a rough dielectric coat (microfacet reflection with the dielectric Fresnel term) over an ideal diffuse base, the base handled as in `plastic` with the coat's transmittance tabulated as Mitsuba 3 tabulates it (light masked after refraction is lost). One-sided.
Mitsuba 3: the same parameters and defaults; the roughness is isotropic and not a texture, as in Mitsuba 3.
uses: microfacet
| parameter | type | default | meaning | Mitsuba 3 |
| int_ior | float or string | `polypropylene` (1.49) | the coat's index of refraction: a positive number or a named material | same |
| ext_ior | float or string | `air` (1.000277) | the index of the medium outside | same |
| diffuse_reflectance | spectrum or texture | 0.5 | the base's albedo | same |
| specular_reflectance | spectrum or texture | 1 | a factor on the specular reflection | same |
| nonlinear | boolean | false | the base's colour shifts with internal scattering | same |
*/
#include "bsdfs/roughplastic.h"

#include "bsdfs/bsdf_parameters.h"
#include "bsdfs/microfacet_interface.h"
#include "core/sampling.h"
#include "optics/fresnel.h"

namespace columba {

namespace {
// The mean of f(wi, m) over the normals visible from the direction with cos(theta) = mu: midpoints
// of the visible-normal sampler's unit square.
template <typename F>
float meanOverVisibleNormals(const MicrofacetDistribution& distribution, float mu, const F& f) {
  constexpr int kSteps = 32;
  const Vec3 wi(safeSqrt(1.0f - mu * mu), 0.0f, mu);
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i)
    for (int j = 0; j < kSteps; ++j)
      sum += f(wi, distribution.sampleVisible(wi, Vec2((i + 0.5f) / kSteps, (j + 0.5f) / kSteps)));
  return float(sum / (kSteps * kSteps));
}
}  // namespace

float RoughPlasticBSDF::coatReflectance(const MicrofacetDistribution& distribution, float mu, float eta) {
  // F(wi.m) G1(wo, m): reflection about a visible normal escapes unless the microsurface masks wo.
  return meanOverVisibleNormals(distribution, mu, [&](const Vec3& wi, const Vec3& m) {
    const Vec3 wo = reflect(wi, m);
    return cosTheta(wo) > 0.0f ? fresnelDielectric(dot(wi, m), eta) * distribution.G1(wo, m) : 0.0f;
  });
}

float RoughPlasticBSDF::coatTransmittance(const MicrofacetDistribution& distribution, float mu, float eta) {
  // (1 - F(wi.m)) G1(wt, m), wt refracted through m: what the microsurface masks after refraction
  // does not reach the base.
  return meanOverVisibleNormals(distribution, mu, [&](const Vec3& wi, const Vec3& m) {
    const float cosI = dot(wi, m), sinT2 = (1.0f - cosI * cosI) / (eta * eta);
    if (cosI <= 0.0f || sinT2 >= 1.0f) return 0.0f;  // no refraction: total internal reflection
    const Vec3 wt = refractThrough(wi, m, cosI, eta, std::sqrt(1.0f - sinT2));
    return cosTheta(wt) < 0.0f ? (1.0f - fresnelDielectric(cosI, eta)) * distribution.G1(wt, m) : 0.0f;
  });
}

RoughPlasticBSDF::RoughPlasticBSDF(MicrofacetDistribution distribution, float eta, SpectrumParameter diffuseReflectance,
                                   SpectrumParameter specularReflectance, bool nonlinear)
    : distribution_(distribution),
      eta_(eta),
      diffuseReflectance_(std::move(diffuseReflectance)),
      specularReflectance_(std::move(specularReflectance)),
      nonlinear_(nonlinear) {
  float d = diffuseReflectance_.meanValue(), s = specularReflectance_.meanValue();
  specularSamplingWeight_ = d + s > 0.0f ? s / (d + s) : 0.5f;

  // Grazing directions are nudged off the horizon, where the sampler is undefined.
  for (int i = 0; i < kTableSize; ++i)
    externalTransmittance_[i] = coatTransmittance(distribution_, std::max(float(i) / (kTableSize - 1), 1e-4f), eta_);

  // 2 * integral of R(mu) mu dmu = mean of R(sqrt(s)) over s in [0, 1] (midpoint rule).
  constexpr int kSteps = 32;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) sum += coatReflectance(distribution_, std::sqrt((i + 0.5f) / kSteps), 1.0f / eta_);
  internalReflectance_ = float(sum / kSteps);
}

float RoughPlasticBSDF::externalTransmittance(float mu) const {
  float x = clampf(mu, 0.0f, 1.0f) * (kTableSize - 1);
  int i = std::min(int(x), kTableSize - 2);
  return lerp(x - i, externalTransmittance_[i], externalTransmittance_[i + 1]);
}

float RoughPlasticBSDF::specularProbability(float cosI) const {
  float reflected = 1.0f - externalTransmittance(cosI);
  float specular = reflected * specularSamplingWeight_;
  float diffuse = (1.0f - reflected) * (1.0f - specularSamplingWeight_);
  return specular + diffuse > 0.0f ? specular / (specular + diffuse) : 0.0f;
}

Spectrum RoughPlasticBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return Spectrum(0.0f);
  Vec3 m = normalize(wi + wo);
  float specular =
      fresnelDielectric(dot(wi, m), eta_) * distribution_.D(m) * distribution_.G(wi, wo, m) / (4.0f * cosTheta(wi));
  Spectrum kd = diffuseReflectance_.eval(ctx.point, wl);
  Spectrum base =
      kd / (nonlinear_ ? Spectrum(1.0f) - kd * internalReflectance_ : Spectrum(1.0f - internalReflectance_));
  float transmission = externalTransmittance(cosTheta(wi)) * externalTransmittance(cosTheta(wo));
  return specularReflectance_.eval(ctx.point, wl) * specular +
         base * (transmission / (eta_ * eta_) * kInvPi * cosTheta(wo));
}

float RoughPlasticBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return 0.0f;
  Vec3 m = normalize(wi + wo);
  float pSpecular = specularProbability(cosTheta(wi));
  return pSpecular * distribution_.visiblePdf(wi, m) / (4.0f * dot(wo, m)) +
         (1.0f - pSpecular) * cosineHemispherePdf(cosTheta(wo));
}

std::optional<BSDFSample> RoughPlasticBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                   float uComponent, Vec2 u) const {
  if (cosTheta(wi) <= 0.0f) return std::nullopt;
  BSDFSample s;
  if (uComponent < specularProbability(cosTheta(wi)))
    s.wo = reflect(wi, distribution_.sampleVisible(wi, u));
  else
    s.wo = sampleCosineHemisphere(u);
  // Both lobes can produce any direction: weight by the mixture density (one-sample MIS).
  s.pdf = pdf(ctx, wi, s.wo, wl);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = eval(ctx, wi, s.wo, wl) / s.pdf;
  return s;
}

std::shared_ptr<Object> makeRoughPlasticBSDF(const Properties& props) {
  MicrofacetDistribution distribution = readMicrofacetDistribution(props, /*allowAnisotropic=*/false);
  float intIOR = readIOR(props, "int_ior", "polypropylene");
  float extIOR = readIOR(props, "ext_ior", "air");
  return std::make_shared<RoughPlasticBSDF>(
      distribution, intIOR / extIOR,
      readSpectrumParameter(props, "diffuse_reflectance", 0.5f, SpectrumUse::Reflectance),
      readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance),
      props.getBool("nonlinear", false));
}

}  // namespace columba
