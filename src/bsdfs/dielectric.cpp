/*! plugin bsdf dielectric
A smooth interface between two dielectrics: specular reflection and refraction, chosen by the Fresnel reflectance. Refraction scales radiance by (η_i/η_t)².
Mitsuba 3: the same parameters and defaults.
| parameter | type | default | meaning | Mitsuba 3 |
| int_ior | float or string | `bk7` (1.5046) | the index inside: a positive number or a named material | same |
| ext_ior | float or string | `air` (1.000277) | the index outside | same |
| specular_reflectance | spectrum or texture | 1 | a factor on the reflection | same |
| specular_transmittance | spectrum or texture | 1 | a factor on the transmission | same |
*/
#include "bsdfs/dielectric.h"

#include "bsdfs/bsdf_parameters.h"
#include "optics/fresnel.h"

namespace columba {

std::optional<BSDFSample> DielectricBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                 float uComponent, Vec2) const {
  const float cosI = cosTheta(wi);
  // Relative index across the interface as seen from wi's side.
  const float etaTI = cosI >= 0.0f ? eta_ : 1.0f / eta_;
  const FresnelAmplitudes a = fresnelAmplitudes(cosI, etaTI);
  const float reflectance = 0.5f * (a.rs * a.rs + a.rp * a.rp);

  BSDFSample s;
  s.delta = true;
  if (uComponent < reflectance) {
    s.wo = mirrorDirection(wi);
    s.pdf = reflectance;
    s.weight = specularReflectance_.eval(ctx.point, wl);
  } else {
    s.wo = Vec3(-wi.x / etaTI, -wi.y / etaTI, std::copysign(a.cosT, -cosI));
    s.pdf = 1.0f - reflectance;
    s.weight = specularTransmittance_.eval(ctx.point, wl) / (etaTI * etaTI);
  }
  return s;
}

std::shared_ptr<Object> makeDielectricBSDF(const Properties& props) {
  float intIOR = readIOR(props, "int_ior", "bk7");
  float extIOR = readIOR(props, "ext_ior", "air");
  return std::make_shared<DielectricBSDF>(
      intIOR / extIOR, readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance),
      readSpectrumParameter(props, "specular_transmittance", 1.0f, SpectrumUse::Reflectance));
}

}  // namespace columba
