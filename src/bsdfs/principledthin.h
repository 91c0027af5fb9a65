#pragma once
// Mitsuba 3's `principledthin` BSDF: the principled model for a sheet with no thickness (leaves,
// paper, cloth), after Burley 2015, section 5.3. Both sides look the same, and light crossing the
// sheet is not bent. Lobes:
// - specular reflection (weight spec_trans): GGX, the dielectric Fresnel term blended toward a
//   base-tinted Schlick term by spec_tint;
// - specular transmission (weight spec_trans): the reflection lobe mirrored through the sheet,
//   tinted by base_color, with the roughness scaled by 0.65 eta - 0.35 (Burley 2015, figure 15);
// - diffuse reflection (weight (1 - spec_trans)(1 - diff_trans / 2)): Disney's diffuse with
//   flatness and sheen, as in `principled`;
// - diffuse transmission (weight (1 - spec_trans) diff_trans / 2): Lambertian, tinted by
//   base_color.
// Each lobe is sampled with its weight times its sampling rate (the specular ones with half).
#include <memory>
#include "bsdfs/bsdf.h"
#include "bsdfs/microfacet.h"
#include "bsdfs/point_material_bsdf.h"
#include "bsdfs/principled_parameters.h"
#include "core/properties.h"

namespace columba {

// The parameters of `principledthin` at one shading point and the quantities derived from them.
struct PrincipledThinMaterial {
  Spectrum baseColor;
  Spectrum tint;  // the base colour at unit luminance
  float roughness, specTrans;
  float diffTrans;  // halved: the transmitted share of the diffuse part
  float eta, specTint, sheen, sheenTint, flatness;
  MicrofacetDistribution reflection, transmission;
};

class PrincipledThinBSDF : public PointMaterialBSDF<PrincipledThinMaterial> {
 public:
  explicit PrincipledThinBSDF(PrincipledThinParameters parameters);
  bool samplesAllItScatters() const override {
    return p_.specularReflectionSamplingRate > 0.0f && p_.specularTransmissionSamplingRate > 0.0f &&
           p_.diffuseReflectionSamplingRate > 0.0f && p_.diffuseTransmissionSamplingRate > 0.0f;
  }

 private:
  using Material = PrincipledThinMaterial;
  // Probabilities of the four sampling strategies.
  struct Strategies {
    float specularReflection = 0.0f, specularTransmission = 0.0f;
    float diffuseReflection = 0.0f, diffuseTransmission = 0.0f;
  };
  Material materialAt(const BSDFContext& ctx, const Wavelengths& wl) const override;
  Spectrum valueFor(const Material& material, const Vec3& wi, const Vec3& wo) const override;
  float densityFor(const Material& material, const Vec3& wi, const Vec3& wo) const override;
  std::optional<BSDFSample> sampleFor(const Material& material, const Vec3& wi, float uComponent,
                                      Vec2 u) const override;
  Strategies strategies(const Material& material) const;

  PrincipledThinParameters p_;
};

std::shared_ptr<Object> makePrincipledThinBSDF(const Properties& props);

}  // namespace columba
