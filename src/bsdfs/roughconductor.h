#pragma once
// Rough metal (Mitsuba's `roughconductor`): microfacet reflection (Walter et al. 2007) with a
// conductor's Fresnel term, sampled through the visible normals. One-sided.
#include <memory>
#include <optional>
#include "bsdfs/bsdf.h"
#include "bsdfs/bsdf_parameters.h"
#include "bsdfs/microfacet_roughness.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class RoughConductorBSDF : public BSDF {
 public:
  // `ior`: the metal's complex index relative to the outside; without it every microfacet is a
  // perfect mirror (Fresnel = 1).
  RoughConductorBSDF(MicrofacetRoughness roughness, std::optional<ConductorIndexParameter> ior,
                     SpectrumParameter specularReflectance);
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

 private:
  // Specular reflectance times the Fresnel reflectance at cos(wi, m) = cosI.
  Spectrum reflectance(const TexturePoint& p, float cosI, const Wavelengths& wl) const;

  MicrofacetRoughness roughness_;
  std::optional<ConductorIndexParameter> ior_;
  SpectrumParameter specularReflectance_;
};

// <bsdf type="roughconductor">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeRoughConductorBSDF(const Properties& props);

}  // namespace columba
