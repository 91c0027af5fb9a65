/*! plugin bsdf conductor
Smooth metal: a perfect mirror weighted by the metal's Fresnel reflectance at each wavelength. One-sided.
Mitsuba 3: the same parameters and named materials; five of them (Ag, Al, Au, Cr, Cu) from other published tables.
uses: conductor
| parameter | type | default | meaning | Mitsuba 3 |
| specular_reflectance | spectrum or texture | 1 | a factor on the reflection | same |
*/
#include "bsdfs/conductor.h"

#include "bsdfs/bsdf_parameters.h"

namespace columba {

std::optional<BSDFSample> ConductorBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float,
                                                Vec2) const {
  if (cosTheta(wi) <= 0.0f) return std::nullopt;
  BSDFSample s;
  s.wo = mirrorDirection(wi);
  s.pdf = 1.0f;
  s.delta = true;
  s.weight = conductorReflectance(ior_, specularReflectance_.eval(ctx.point, wl), cosTheta(wi), ctx.point, wl);
  return s;
}

std::shared_ptr<Object> makeConductorBSDF(const Properties& props) {
  std::optional<ConductorIndexParameter> ior = readConductorIndex(props);
  return std::make_shared<ConductorBSDF>(
      std::move(ior), readSpectrumParameter(props, "specular_reflectance", 1.0f, SpectrumUse::Reflectance));
}

}  // namespace columba
