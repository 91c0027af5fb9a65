#pragma once
// Smooth plastic (Mitsuba's `plastic`): a smooth dielectric coat that reflects specularly (delta)
// over an ideal diffuse base. Light refracts into the coat, scatters off the base, and leaves
// after any number of internal reflections at the coat's underside, each with the diffuse
// Fresnel reflectance; the diffuse lobe keeps a Lambertian shape scaled by the transmittances
// into and out of the coat. One-sided.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class PlasticBSDF : public BSDF {
 public:
  // eta = coat index / outside index. With `nonlinear`, the base's colour also tints each
  // internal bounce (Kd / (1 - Kd Ri)) instead of only the first (Kd / (1 - Ri)).
  PlasticBSDF(float eta, SpectrumParameter diffuseReflectance, SpectrumParameter specularReflectance, bool nonlinear);
  // The diffuse component only.
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

 private:
  // Probability of choosing the specular reflection for Fresnel reflectance `fresnelI` at wi.
  float specularProbability(float fresnelI) const;

  float eta_;
  SpectrumParameter diffuseReflectance_, specularReflectance_;
  bool nonlinear_;
  float internalReflectance_;     // diffuse Fresnel reflectance at the coat's underside
  float specularSamplingWeight_;  // mean specular / (mean specular + mean diffuse reflectance)
};

// <bsdf type="plastic">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makePlasticBSDF(const Properties& props);

}  // namespace columba
