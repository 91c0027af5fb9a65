/*! plugin bsdf thindielectric
A thin sheet of dielectric (a window pane): light is mirrored with the sheet's reflectance or passes straight through, on either side. With the Fresnel reflectance r, the light bouncing between the faces sums to R = 2r / (1 + r) and T = 1 − R. The transmission is a pass-through, so shadow rays cross the sheet with weight T.
Mitsuba 3: the same parameters and defaults; shadow rays pass through the sheet.
| parameter | type | default | meaning | Mitsuba 3 |
| int_ior | float or string | `bk7` (1.5046) | the sheet's index: a positive number or a named material | same |
| ext_ior | float or string | `air` (1.000277) | the index around it | same |
| specular_reflectance | spectrum or texture | 1 | a factor on the reflection | same |
| specular_transmittance | spectrum or texture | 1 | a factor on the transmission | same |
*/
#include "bsdfs/thindielectric.h"

#include "bsdfs/bsdf_parameters.h"
#include "optics/fresnel.h"

namespace columba {

float ThinDielectricBSDF::sheetReflectance(float cosI) const {
  FresnelAmplitudes a = fresnelAmplitudes(std::abs(cosI), eta_);
  float r = 0.5f * (a.rs * a.rs + a.rp * a.rp);
  return r < 1.0f ? 2.0f * r / (1.0f + r) : 1.0f;
}

std::optional<BSDFSample> ThinDielectricBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                     float uComponent, Vec2) const {
  float R = sheetReflectance(cosTheta(wi));
  BSDFSample s;
  s.delta = true;
  if (uComponent < R) {
    s.wo = mirrorDirection(wi);
    s.pdf = R;
    s.weight = specularReflectance_.eval(ctx.point, wl);
  } else {
    s.wo = -wi;
    s.pdf = 1.0f - R;
    s.weight = specularTransmittance_.eval(ctx.point, wl);
    s.passThrough = true;
  }
  return s;
}

Spectrum ThinDielectricBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  return specularTransmittance_.eval(ctx.point, wl) * (1.0f - sheetReflectance(cosTheta(wi)));
}

std::shared_ptr<Object> makeThinDielectricBSDF(const Properties& props) {
  float intIOR = readIOR(props, "int_ior", "bk7");
  float extIOR = readIOR(props, "ext_ior", "air");
  return std::make_shared<ThinDielectricBSDF>(
      intIOR / extIOR, readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance),
      readSpectrumParameter(props, "specular_transmittance", 1.0f, SpectrumUse::Reflectance));
}

}  // namespace columba
