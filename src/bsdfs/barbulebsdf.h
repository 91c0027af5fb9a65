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
#include <memory>
#include <vector>
#include "barbule/cross_section.h"
#include "barbule/parameters.h"
#include "bsdfs/bsdf.h"
#include "bsdfs/per_point_parameters.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

// Node counts of the deterministic parts of the model and its sampler. The TRT lobe is a
// Gauss-Legendre average over visible normals (offsets across the lit arc x longitudinal angles;
// one longitudinal node sits at the mean angle). Against 24 x 8 nodes, the default 4 x 1 has a
// relative L1 error of the TRT lobe over outgoing directions of about 0.7 % on average and 3 % at
// worst (grazing incidence, where the film's transmission changes fast along the arc); 8 x 2
// reaches 0.1 % / 0.6 % at four times the cost. The sampler chooses between R and TRT at the
// sampled offset in proportion to the lobes' weights at `lobeShareNodes` offsets spread evenly over
// the lit arc (2 to kMaxLobeShareNodes), linear between them; it only steers sampling (pdf()
// integrates that share exactly), so the node count changes noise, never the expected image.
inline constexpr int kMaxLobeShareNodes = 8;
struct BarbuleQuadrature {
  int offsetNodes = 4;
  int thetaNodes = 1;
  int lobeShareNodes = 4;
};

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
  struct Lobes {
    Spectrum reflection, trt;
  };
  Lobes evalLobes(const BSDFContext& ctx, const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const;
  // Coverage r(omega_i): the fraction of light from omega_i meeting the reflective arc (T = 1 - r).
  float coverage(const BSDFContext& ctx, const Vec3& omegaI) const;
  // The density pdf() reports, by the lobe that draws wo: pdf() is their sum.
  struct LobeDensities {
    float reflection = 0.0f, trt = 0.0f;
    float total() const { return reflection + trt; }
  };
  LobeDensities lobePdfs(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const;

  const BarbuleParameters& parameters() const { return params_; }
  Role role() const { return role_; }

  void setTextures(BarbuleTextures textures) { textures_ = std::move(textures); }
  // Where a scene gave H, mu and height, for the warning when a shape's values win over them.
  void setSceneSources(std::shared_ptr<const PerPointParameterSources> sources) { sceneSources_ = std::move(sources); }
  void noteValuesGivenByShape(const SurfaceAttributeSet& everywhere, const std::string& shape) const override {
    if (sceneSources_) sceneSources_->warnIfShadowed(everywhere, shape);
  }

 private:
  struct PointModel;
  struct Incident;
  struct LobeChoice;
  struct Outgoing;

  // The cross-section with the point's own b, mu and H, when textures or its attributes give any.
  std::optional<BarbuleCrossSection> overriddenGeometry(const BSDFContext& ctx) const;
  // The film thickness at the point (um).
  float cortexThickness(const BSDFContext& ctx) const;
  // omega_i's lit arc, coverage and whether it scatters; `arc` when already computed.
  Incident incident(const PointModel& point, const Vec3& w) const;
  Incident incident(const PointModel& point, const Vec3& w, const LitArc& arc) const;
  // omega_o, whose lit arc is `arc`, with what the pair (omega_i, omega_o) shares.
  Outgoing outgoing(const PointModel& point, const Incident& in, const Vec3& wo, const LitArc& arc) const;
  // The same without the common lit interval: what R needs (the half vector and its normal's lighting).
  Outgoing mirrorGeometry(const PointModel& point, const Incident& in, const Vec3& wo, const LitArc& arc) const;

  // Evaluation, one scheme. eval* gives the value f |cos omega_o|, evalLobes* the lobes without a
  // cosine, evalPdf* the value with the sampling density. eval and evalLobes (public) start from a
  // context and directions; *At starts from the point's model and omega_i's quantities (`fromWi`)
  // with wo and its lit arc; *ForPair from a prepared pair (omega_i, omega_o). eval, evalAt and
  // evalPdfAt take the interface's (wi, wo) and apply the role; evalLobes and *ForPair take the
  // model's (omega_i, omega_o).
  Spectrum evalAt(const PointModel& point, const Incident& fromWi, const Vec3& wo, const LitArc& woArc) const;
  // `mirrorVisible`: for an R sample just drawn, the share of visible longitudinal angles it was
  // drawn with (MirrorVisibleAngles::visibleFraction()); negative otherwise.
  BSDFEvalPdf evalPdfAt(const PointModel& point, const Incident& fromWi, const LobeChoice& choice, const Vec3& wo,
                        const LitArc& woArc, float mirrorVisible = -1.0f) const;
  Spectrum evalForPair(const PointModel& point, const Incident& in, const Outgoing& out) const;
  Lobes evalLobesForPair(const PointModel& point, const Incident& in, const Outgoing& out) const;
  // The lobes of a pair.
  Spectrum reflection(const PointModel& point, const Incident& in, const Outgoing& out) const;
  Spectrum trt(const PointModel& point, const Incident& in, const Outgoing& out) const;
  // What emitter candidates are chosen by (BSDFVertexRequest::chooseLight), with omega_i = wi: R
  // exactly, the R lobe being what varies fast across an area light, and a bound of TRT.
  Spectrum resamplingTarget(const PointModel& point, const Incident& in, const Vec3& wo, const LitArc& woArc) const;
  // The TRT integrand's mean over the longitudinal angles at one offset node (thetaNodes > 1),
  // per wavelength.
  Spectrum trtLongitudinalMean(const PointModel& point, float projectedIn, float projectedOut, float inY,
                               float outY) const;

  LobeChoice lobeChoice(const PointModel& point, const Incident& in, bool passThroughByCaller) const;
  static float transmission(const BarbuleCrossSection& geometry, const Incident& in);
  LobeDensities samplingPdfs(const PointModel& point, const Incident& in, const LobeChoice& choice, const Outgoing& out,
                             float mirrorVisible = -1.0f) const;
  static float trtSamplingPdf(const Incident& in, const LobeChoice& choice, const Outgoing& out);
  // sample, once the point's model, omega_i's quantities and the lobe choice are known; without
  // `withPdf` the sample's pdf is left 0.
  std::optional<BSDFSample> sampleAt(const PointModel& point, const Incident& in, const LobeChoice& choice,
                                     float uComponent, Vec2 u, bool withPdf = true) const;

  BarbuleParameters params_;
  Role role_;
  BarbuleCrossSection geometry_;
  int offsetNodeCount_;
  std::vector<FloatLanes> offsetNodes_, offsetWeights_;  // in groups of four lanes
  std::vector<float> thetaNodes_, thetaWeights_;
  int lobeShareNodes_;
  BarbuleTextures textures_;
  std::shared_ptr<const PerPointParameterSources> sceneSources_;
};

// <bsdf type="barbulebsdf"> and <bsdf type="barbulebsdfev">: their parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeBarbuleBSDF(const Properties& props);
std::shared_ptr<Object> makeBarbuleBSDFEv(const Properties& props);

}  // namespace columba
