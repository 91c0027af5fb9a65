/*! plugin bsdf diffuse
An ideal diffuse (Lambertian) reflector; the BSDF of a shape that has none.
Mitsuba 3: as Mitsuba 3's `diffuse`.
| parameter | type | default | meaning | Mitsuba 3 |
| reflectance | spectrum or texture | 0.5 | the albedo; an RGB colour is clamped to [0, 1] | same |
*/
#include "bsdfs/diffuse.h"

#include "core/sampling.h"

namespace columba {

Spectrum DiffuseBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) <= 0.0f || cosTheta(wo) <= 0.0f) return Spectrum(0.0f);
  return reflectance_.eval(ctx.point, wl) * (kInvPi * cosTheta(wo));
}

float DiffuseBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths&) const {
  if (cosTheta(wi) <= 0.0f) return 0.0f;
  return cosineHemispherePdf(cosTheta(wo));
}

std::optional<BSDFSample> DiffuseBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float,
                                              Vec2 u) const {
  if (cosTheta(wi) <= 0.0f) return std::nullopt;
  BSDFSample s;
  s.wo = sampleCosineHemisphere(u);
  s.pdf = cosineHemispherePdf(cosTheta(s.wo));
  if (s.pdf <= 0.0f) return std::nullopt;
  s.weight = reflectance_.eval(ctx.point, wl);
  return s;
}

std::shared_ptr<Object> makeDiffuseBSDF(const Properties& props) {
  return std::make_shared<DiffuseBSDF>(readSpectrumParameter(props, "reflectance", 0.5f, SpectrumUse::Reflectance));
}

}  // namespace columba
