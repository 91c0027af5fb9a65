#pragma once
// Rough interface between two dielectrics (Mitsuba's `roughdielectric`): microfacet reflection
// and refraction (Walter et al. 2007, "Microfacet models for refraction through rough surfaces"),
// sampled through the normals visible from wi, then reflection with the Fresnel reflectance at
// that normal as its probability. Paths start at the camera: refraction scales the value by
// (n_wi / n_wo)^2 as the smooth `dielectric` does (radiance compressed on the denser side).
#include <memory>
#include "bsdfs/bsdf.h"
#include "bsdfs/microfacet_roughness.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class RoughDielectricBSDF : public BSDF {
 public:
  // eta = interior / exterior index; the normal (local +z) points to the exterior.
  RoughDielectricBSDF(MicrofacetRoughness roughness, float eta, SpectrumParameter specularReflectance,
                      SpectrumParameter specularTransmittance);
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

 private:
  MicrofacetRoughness roughness_;
  float eta_;
  SpectrumParameter specularReflectance_, specularTransmittance_;
};

// <bsdf type="roughdielectric">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeRoughDielectricBSDF(const Properties& props);

}  // namespace columba
