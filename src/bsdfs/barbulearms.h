#pragma once
// A vane of barbules whose cross-section is a chain of flat arms (barbule/armed_cross_section.h):
// the V, boomerang and three-mirror barbules that the ellipse cannot describe, such as Lawes'
// parotia's breast barbules (Stavenga et al. 2011). Its lobes are
//   R  specular reflection off each arm's film-coated side (the cortex over any `layers`), a
//      microfacet lobe whose normals come from the arms' curvature, lit and seen only where the
//      barbule itself and its neighbours leave the point open to both directions;
//   T  straight through between the barbules, and past their uncoated sides (a pass-through).
// Left out, with reasons in docs/model.md ("Cross-sections made of arms"): the TRT lobe (light the
// stack transmits is taken as absorbed inside the barbule), light reflected from one arm onto
// another, and per-point cross-sections (a feather's per-vertex mu and H).
//
// Frame, directions and conventions as barbulebsdf's (bsdfs/barbulebsdf.h): z along the vane
// normal, y along the barbule axis; omega_i = wi; R is symmetric in its directions.
#include <atomic>
#include <memory>

#include "barbule/armed_cross_section.h"
#include "barbule/lobe_source.h"
#include "barbule/parameters.h"
#include "bsdfs/bsdf.h"
#include "bsdfs/per_point_parameters.h"
#include "core/properties.h"

namespace columba {

class BarbuleArmsBSDF : public BSDF, public BarbuleLobeSource {
 public:
  // `film` gives the cortex and the layers under it (its cross-section values are not read).
  BarbuleArmsBSDF(ArmedCrossSection geometry, BarbuleParameters film);

  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return true; }
  void noteValuesGivenByShape(const ShapePointValues& given) const override;
  // The arms' flat faces above p = 3, as barbulebsdf's (docs/model.md, "Which estimators converge").
  bool hasSingularValues() const override { return film_.profileExponent > 3.0f; }
  bool followsSurfaceAxis() const override { return true; }

  const ArmedCrossSection& geometry() const { return geometry_; }
  // The film's parameters, with the cross-section's b, profile exponent, mu and the spacing H it
  // uses (the contact spacing where the scene's is smaller); phi_0, phi_1 and melanin unused.
  const BarbuleParameters& parameters() const { return film_; }
  // The fraction of light from omega_i meeting a coated side (T = 1 - coverage).
  float coverage(const Vec3& omegaI) const override;
  // R (eval without its cosine) and a TRT of 0, for the virtual measurements.
  BarbuleLobes lobes(const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const override;

  // Where the scene gave `height` (for the warning when a feather's values win over it) and where
  // it declared the BSDF.
  void setSceneSources(std::shared_ptr<const PerPointParameterSources> heightSource, SourceLocation declaredAt) {
    heightSource_ = std::move(heightSource);
    declaredAt_ = std::move(declaredAt);
  }

 private:
  BSDFEvalPdf valueAndPdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const;

  ArmedCrossSection geometry_;
  BarbuleParameters film_;
  std::shared_ptr<const PerPointParameterSources> heightSource_;
  SourceLocation declaredAt_;
  // Whether a feather's per-vertex cross-section values were warned of (shared: the BSDF stays movable).
  std::shared_ptr<std::atomic<bool>> warnedShapeValues_ = std::make_shared<std::atomic<bool>>(false);
};

// <bsdf type="barbulearms">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeBarbuleArmsBSDF(const Properties& props);

}  // namespace columba
