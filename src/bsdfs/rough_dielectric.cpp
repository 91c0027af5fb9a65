#include "bsdfs/rough_dielectric.h"

#include "bsdfs/bsdf_parameters.h"
#include "optics/fresnel.h"

namespace columba {

namespace {
Vec3 mirrored(const Vec3& w) { return Vec3(w.x, w.y, -w.z); }
}  // namespace

RoughDielectricBSDF::RoughDielectricBSDF(MicrofacetRoughness roughness, float eta,
                                         SpectrumParameter specularReflectance, SpectrumParameter specularTransmittance)
    : roughness_(std::move(roughness)),
      eta_(eta),
      specularReflectance_(std::move(specularReflectance)),
      specularTransmittance_(std::move(specularTransmittance)) {}

RoughDielectricBSDF::Pair RoughDielectricBSDF::pairOf(const Vec3& wi, const Vec3& wo) const {
  Pair p;
  if (cosTheta(wi) == 0.0f || cosTheta(wo) == 0.0f) return p;
  bool inside = cosTheta(wi) < 0.0f;
  p.wi = inside ? mirrored(wi) : wi;
  p.wo = inside ? mirrored(wo) : wo;
  p.eta = inside ? 1.0f / eta_ : eta_;
  p.reflection = cosTheta(p.wo) > 0.0f;
  // Reflection: the half vector; refraction: Walter's -(wi + eta wo), both turned toward +z.
  Vec3 h = p.reflection ? p.wi + p.wo : -(p.wi + p.eta * p.wo);
  float len = length(h);
  if (!(len > 0.0f)) return p;
  p.m = h / len;
  if (p.m.z < 0.0f) p.m = -p.m;
  // wi must meet the front of m, and wo leave on its side (reflection) or through it (refraction).
  float iDotM = dot(p.wi, p.m), oDotM = dot(p.wo, p.m);
  p.valid = iDotM > 0.0f && (p.reflection ? oDotM > 0.0f : oDotM < 0.0f);
  return p;
}

float RoughDielectricBSDF::value(const MicrofacetDistribution& distribution, const Pair& p, float fresnel) {
  float D = distribution.D(p.m), G = distribution.G(p.wi, p.wo, p.m);
  float iDotM = dot(p.wi, p.m), oDotM = dot(p.wo, p.m);
  if (p.reflection) return fresnel * D * G / (4.0f * cosTheta(p.wi));
  // Walter's f_t |cos wo| = |i.m| |o.m| eta^2 (1 - F) D G / (|i.n| (i.m + eta o.m)^2), times
  // 1 / eta^2 for radiance.
  float denom = iDotM + p.eta * oDotM;
  return (1.0f - fresnel) * D * G * iDotM * std::abs(oDotM) / (cosTheta(p.wi) * denom * denom);
}

float RoughDielectricBSDF::density(const MicrofacetDistribution& distribution, const Pair& p, float fresnel) {
  float visible = distribution.visiblePdf(p.wi, p.m), oDotM = dot(p.wo, p.m);
  if (p.reflection) return fresnel * visible / (4.0f * oDotM);
  // dm / dwo for refraction: eta^2 |o.m| / (i.m + eta o.m)^2.
  float denom = dot(p.wi, p.m) + p.eta * oDotM;
  return (1.0f - fresnel) * visible * p.eta * p.eta * std::abs(oDotM) / (denom * denom);
}

Spectrum RoughDielectricBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo,
                                   const Wavelengths& wl) const {
  Pair p = pairOf(wi, wo);
  if (!p.valid) return Spectrum(0.0f);
  float f = value(roughness_.at(ctx.uv), p, fresnelDielectric(dot(p.wi, p.m), p.eta));
  return (p.reflection ? specularReflectance_ : specularTransmittance_).eval(ctx.uv, wl) * f;
}

float RoughDielectricBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  Pair p = pairOf(wi, wo);
  return p.valid ? density(roughness_.at(ctx.uv), p, fresnelDielectric(dot(p.wi, p.m), p.eta)) : 0.0f;
}

std::optional<BSDFSample> RoughDielectricBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                      float uComponent, Vec2 u) const {
  if (cosTheta(wi) == 0.0f) return std::nullopt;
  bool inside = cosTheta(wi) < 0.0f;
  Vec3 front = inside ? mirrored(wi) : wi;
  float eta = inside ? 1.0f / eta_ : eta_;
  const MicrofacetDistribution distribution = roughness_.at(ctx.uv);
  Vec3 m = distribution.sampleVisible(front, u);
  float cosI = dot(front, m);
  if (!(cosI > 0.0f)) return std::nullopt;
  FresnelAmplitudes a = fresnelAmplitudes(cosI, eta);
  float fresnel = 0.5f * (a.rs * a.rs + a.rp * a.rp);
  bool reflection = uComponent < fresnel;
  Vec3 wo = reflection ? reflect(front, m) : (-front / eta + (cosI / eta - a.cosT) * m);
  // A reflection below the surface or a refraction back above it is light the microfacets'
  // neighbours would stop (and no other half vector could give it): no sample.
  if (reflection != (wo.z > 0.0f)) return std::nullopt;
  if (inside) wo = mirrored(wo);
  Pair p = pairOf(wi, wo);
  if (!p.valid) return std::nullopt;
  fresnel = fresnelDielectric(dot(p.wi, p.m), p.eta);  // at the half vector pdf() sees
  BSDFSample s;
  s.wo = wo;
  s.pdf = density(distribution, p, fresnel);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.weight = (p.reflection ? specularReflectance_ : specularTransmittance_).eval(ctx.uv, wl) *
             (value(distribution, p, fresnel) / s.pdf);
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
