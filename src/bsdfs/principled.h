#pragma once
// Mitsuba 3's `principled` BSDF, after Burley's Disney model (2012 BRDF, 2015 BSDF without the
// subsurface and volume parts). Lobes, with brdf = (1 - metallic)(1 - spec_trans) and
// bsdf = (1 - metallic) spec_trans:
// - main specular reflection: anisotropic GGX, Fresnel a blend of the dielectric's exact term,
//   the base colour's Schlick term (metallic) and a base-tinted Schlick term (spec_tint);
// - specular transmission (bsdf): rough refraction tinted by sqrt(base_color), both ways;
// - diffuse (brdf): Disney's diffuse with retro-reflection, blended toward the subsurface
//   approximation by flatness; with it, where brdf > 0, the sheen, weighted sheen (1 - metallic)
//   and tinted by sheen_tint;
// - clearcoat: GTR1 normals, Schlick Fresnel with R0 = 0.04, weight clearcoat / 4.
// The lobes add up: with a white base the diffuse and specular lobes together reflect more than
// arrives (as in Mitsuba). From below (wi.z < 0) only the dielectric interface remains, weighted
// by bsdf. Sampling picks diffuse, clearcoat or specular with weights brdf, clearcoat / 4 and 1,
// each times its sampling rate; a specular sample reflects with probability 1 - bsdf (1 - F)
// from above and F from below, F the dielectric Fresnel term at the visible normal drawn.
#include <memory>
#include "bsdfs/bsdf.h"
#include "bsdfs/microfacet.h"
#include "bsdfs/point_material_bsdf.h"
#include "bsdfs/principled_parameters.h"
#include "bsdfs/principled_terms.h"
#include "core/properties.h"

namespace columba {

// The parameters of `principled` at one shading point and the quantities derived from them.
struct PrincipledMaterial {
  Spectrum baseColor;
  Spectrum tint;  // the base colour at unit luminance
  float roughness, metallic, specTint, sheen, sheenTint, flatness, clearcoat;
  float diffuseWeight, transmissionWeight;  // brdf and bsdf above
  MicrofacetDistribution specular;
  GTR1Distribution coat;
};

class PrincipledBSDF : public PointMaterialBSDF<PrincipledMaterial> {
 public:
  explicit PrincipledBSDF(PrincipledParameters parameters);
  bool samplesAllItScatters() const override {
    return p_.diffuseSamplingRate > 0.0f && p_.specularSamplingRate > 0.0f && p_.clearcoatSamplingRate > 0.0f;
  }

 private:
  using Material = PrincipledMaterial;
  // Probabilities of the sampling strategies for light arriving on the given side.
  struct Strategies {
    float diffuse = 0.0f, clearcoat = 0.0f, specular = 0.0f;
  };
  Material materialAt(const BSDFContext& ctx, const Wavelengths& wl) const override;
  Spectrum valueFor(const Material& material, const Vec3& wi, const Vec3& wo) const override;
  float densityFor(const Material& material, const Vec3& wi, const Vec3& wo) const override;
  std::optional<BSDFSample> sampleFor(const Material& material, const Vec3& wi, float uComponent,
                                      Vec2 u) const override;
  Strategies strategies(const Material& material, bool front) const;
  // Probability that the specular strategy reflects, given the dielectric Fresnel term.
  static float specularReflectionShare(const Material& material, bool front, float fresnel);
  // The main specular reflection's Fresnel factor on the front side.
  Spectrum frontFresnel(const Material& material, float cosI, float dielectricFresnel) const;

  PrincipledParameters p_;
};

std::shared_ptr<Object> makePrincipledBSDF(const Properties& props);

}  // namespace columba
