#pragma once
// Rough plastic (Mitsuba's `roughplastic`): a rough dielectric coat (microfacet reflection with
// the dielectric Fresnel term) over an ideal diffuse base. One-sided.
//
// The base is handled as in `plastic`, with these approximations:
// - the coat reflects by single scattering only; light its microfacets send back into them is
//   lost rather than scattered again;
// - light enters and leaves the coat with the transmittance T(mu), the mean over the normals
//   visible from the light of (1 - F) G1(refracted direction): light the microsurface masks after
//   refracting is lost, as in Mitsuba 3, so T + R < 1 on a rough coat; tabulated in
//   mu = cos(theta); the refracted lobe's shape is ignored (the base sees diffuse light);
// - internal reflections at the coat's underside are summed as a geometric series with the
//   cosine-weighted average of the rough internal reflectance, and the exiting light is
//   Lambertian times T(mu_o) / eta^2. Light lost to masking inside the coat is not returned,
//   so even a white base reflects less than everything at high roughness (about 0.56 for
//   GGX, alpha = 0.7, eta = 1.49), as in Mitsuba.
#include <array>
#include <memory>
#include "bsdfs/bsdf.h"
#include "bsdfs/microfacet.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class RoughPlasticBSDF : public BSDF {
 public:
  // eta = coat index / outside index. `nonlinear` as for PlasticBSDF.
  RoughPlasticBSDF(MicrofacetDistribution distribution, float eta, SpectrumParameter diffuseReflectance,
                   SpectrumParameter specularReflectance, bool nonlinear);
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

  // Directional albedo of the coat's microfacet reflection for light from a direction with
  // cos(theta) = mu; eta is the index ratio across the coat as seen from that side.
  static float coatReflectance(const MicrofacetDistribution& distribution, float mu, float eta);
  // The fraction of that light the coat lets through into a medium of relative index eta.
  static float coatTransmittance(const MicrofacetDistribution& distribution, float mu, float eta);

 private:
  static constexpr int kTableSize = 64;
  // T(mu), linearly interpolated from the table.
  float externalTransmittance(float mu) const;
  float specularProbability(float cosI) const;

  MicrofacetDistribution distribution_;
  float eta_;
  SpectrumParameter diffuseReflectance_, specularReflectance_;
  bool nonlinear_;
  float specularSamplingWeight_;                         // mean specular / (mean specular + mean diffuse reflectance)
  std::array<float, kTableSize> externalTransmittance_;  // at mu = i / (kTableSize - 1)
  float internalReflectance_;                            // cosine-weighted rough reflectance at the coat's underside
};

// <bsdf type="roughplastic">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeRoughPlasticBSDF(const Properties& props);

}  // namespace columba
