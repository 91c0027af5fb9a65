#pragma once
// The barbule BSDF of rock dove neck feathers (Huang et al. 2022; DESIGN.md §5): a vane of
// parallel barbules with elliptical cross-sections coated by a thin keratin film over melanin.
//   R    specular reflection off the film (thin-film interference), a microfacet lobe whose
//        normal distribution comes from the cross-section's curvature;
//   TRT  light through the film, reflected by the melanin layer and back out: diffuse-like;
//   T    straight through the gaps between barbules: a pass-through (not a bounce).
//
// Frame: z = vane normal n, y = barbule axis t, x across the barbules.
//
// Conventions and decisions:
// - The model's incident direction omega_i is the one whose lit arc, coverage r and film entry
//   the lobes are built on. `barbulebsdf` uses wi (the camera side) as omega_i, as a BSDF-sampled
//   path tracer needs; `barbulebsdfev` (Role::LightIncident) evaluates with omega_i = wo, the
//   light direction, as the paper's emitter-sampled visualisations do, and returns what an
//   imaging scatterometer records, f(omega_light, omega_camera) |cos theta_camera| (the camera's
//   cosine, not the light's). Both sample the same way
//   (from wi) and report the density of that sampler. `barbulebsdf` weighs a sample by the value
//   of the lobe that drew it over that lobe's density (each lobe estimated by its own samples),
//   the twin by eval / pdf; for the
//   evaluation twin this is unbiased wherever eval is reachable from wi (always for R, whose
//   value is symmetric; TRT needs a point lit from both directions either way), but it is meant
//   for emitter sampling.
// - omega_i below the vane (omega_i . n <= 0) reflects nothing; light passes with the coverage of
//   -omega_i, the same line through the layer, so T is the same in both directions of travel
//   (the paper's implementation uses the same in-plane line).
//   Outgoing directions below the vane are allowed: the lower part of the arc reflects down
//   through the gaps.
// - Reciprocity: f_R is symmetric in its two directions when both are above the vane (I_R at
//   omega_i . m = omega_o . m, D(m), a symmetric visibility and longitudinal shadowing). f_TRT is
//   not: it averages over the normals lit from omega_i and is scaled by omega_i's coverage.
// - Normalisation (derived in barbulebsdf.cpp): the integral of f_R cos(theta_o) over omega_o is
//   r times the mean over visible normals of I_R times the visibility toward omega_o, and the
//   same holds for TRT; with T = 1 - r the total never exceeds 1.
#include <atomic>
#include <memory>
#include <vector>
#include "barbule/model.h"
#include "bsdfs/bsdf.h"
#include "bsdfs/per_point_parameters.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

// Parameters a scene gives as textures, per point, in place of BarbuleParameters' constants and
// of the shape's per-point values; only the textured ones are read.
struct BarbuleTextures {
  FloatParameter b = 0.0f, mu = 0.0f, H = 0.0f, height = 0.0f;
};

class BarbuleBSDF : public BSDF {
 public:
  enum class Role { CameraIncident, LightIncident };

  explicit BarbuleBSDF(const BarbuleParameters& params, Role role = Role::CameraIncident,
                       BarbuleQuadrature quadrature = {});

  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  BSDFVertexQueries queryVertex(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                const BSDFVertexRequest& request) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return true; }
  // R's value and a bound of TRT, none of TRT's quadrature (resamplingTarget), as barbulebsdf.
  bool hasCheapResamplingTargets() const override { return role_ == Role::CameraIncident; }

  // The model's two non-delta lobes f(omega_i, omega_o) (without any cosine), omega_i first
  // whatever the role: for plots and tests.
  using Lobes = BarbuleLobes;
  Lobes evalLobes(const BSDFContext& ctx, const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const;
  // Coverage r(omega_i): the fraction of light from omega_i meeting the reflective arc (T = 1 - r).
  float coverage(const BSDFContext& ctx, const Vec3& omegaI) const;
  // The density pdf() reports, by the lobe that draws wo: pdf() is their sum.
  using LobeDensities = BarbuleLobeDensities;
  LobeDensities lobePdfs(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const;

  const BarbuleModel& model() const { return model_; }
  const BarbuleParameters& parameters() const { return model_.parameters(); }
  Role role() const { return role_; }

  void setTextures(BarbuleTextures textures) { textures_ = std::move(textures); }
  // Where a scene gave H, mu and height, for the warning when a shape's values win over them;
  // where it declared the BSDF, for the error when a shape chooses a layer stack it lacks; and
  // where it gave layers_1, for the warning when a shape chooses none.
  void setSceneSources(std::shared_ptr<const PerPointParameterSources> sources, SourceLocation declaredAt,
                       SourceLocation numberedStacksAt) {
    sceneSources_ = std::move(sources);
    declaredAt_ = std::move(declaredAt);
    numberedStacksAt_ = std::move(numberedStacksAt);
  }
  void noteValuesGivenByShape(const ShapePointValues& given) const override;
  // A superellipse's flat faces above p = 3 (docs/model.md, "Which estimators converge").
  bool hasSingularValues() const override { return model_.parameters().profileExponent > 3.0f; }
  bool followsSurfaceAxis() const override { return true; }

 private:
  // The model at the point: the cross-section with the point's own b, mu and H where textures or
  // its attributes give any, and the film with its thickness there.
  BarbulePointModel pointModel(const BSDFContext& ctx, const Wavelengths& wl) const;
  std::optional<BarbuleCrossSection> overriddenGeometry(const BSDFContext& ctx) const;
  float cortexThickness(const BSDFContext& ctx) const;  // micrometres
  int layerStack(const BSDFContext& ctx) const;

  // f |cos theta_o| for the interface's (wi, wo), the role deciding which is omega_i; `fromWi`
  // holds wi's quantities, `woArc` wo's lit arc. With the density of the sampler (from wi) too.
  Spectrum roleValue(const BarbulePointModel& point, const BarbuleIncident& fromWi, const Vec3& wo,
                     const LitArc& woArc) const;
  BSDFEvalPdf roleValueAndPdf(const BarbulePointModel& point, const BarbuleScattering& fromWi, const Vec3& wo,
                              const LitArc& woArc, float mirrorVisible = -1.0f) const;
  // sample, once the point's model and what sampling needs from wi are known; without `withPdf`
  // the sample's pdf is left 0.
  std::optional<BSDFSample> sampleAt(const BarbulePointModel& point, const BarbuleScattering& fromWi, float uComponent,
                                     Vec2 u, bool withPdf = true) const;

  BarbuleModel model_;
  Role role_;
  BarbuleTextures textures_;
  std::shared_ptr<const PerPointParameterSources> sceneSources_;
  SourceLocation declaredAt_, numberedStacksAt_;
  // Whether a feather choosing no stack was warned of (shared, so that the BSDF stays movable).
  std::shared_ptr<std::atomic<bool>> warnedNoStacks_ = std::make_shared<std::atomic<bool>>(false);
};

// <bsdf type="barbulebsdf"> and <bsdf type="barbulebsdfev">: their parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeBarbuleBSDF(const Properties& props);
std::shared_ptr<Object> makeBarbuleBSDFEv(const Properties& props);

}  // namespace columba
