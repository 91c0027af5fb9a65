#pragma once
// The barbule model at one shading point (docs/model.md §3-8): the cross-section with the point's
// own tilt, spacing and semi-axis, the keratin film with its thickness (and any layers under it),
// and the melanin under it,
// at the path's wavelengths. It answers in the model's own directions (omega_i, whose lit arc,
// coverage and film entry the lobes are built on, and omega_o); the BSDF plug-in
// (bsdfs/barbulebsdf.h) decides which of a path's directions is omega_i.
#include <array>
#include <limits>
#include <optional>
#include <vector>

#include "barbule/barbule_film.h"
#include "barbule/cross_section.h"
#include "barbule/normals.h"
#include "barbule/parameters.h"
#include "core/fast_math.h"
#include "core/spectrum.h"

namespace columba {

// Node counts of the deterministic parts of the model and its sampler. The TRT lobe is a
// Gauss-Legendre average over visible normals (offsets across the lit arc x longitudinal angles;
// one longitudinal node sits at the mean angle); the default 4 x 1 is within a few per cent of a
// fine quadrature (docs/performance.md, "The barbule model and its sampling"). The sampler
// chooses between R and TRT at the sampled offset in proportion to the lobes' weights at
// `lobeShareNodes` offsets spread evenly over the lit arc (2 to kMaxLobeShareNodes), linear
// between them; it only steers sampling (the density integrates that share exactly), so the node
// count changes noise, never the expected image.
inline constexpr int kMaxLobeShareNodes = 8;
struct BarbuleQuadrature {
  int offsetNodes = 4;
  int thetaNodes = 1;
  int lobeShareNodes = 4;
};

// The quadrature's nodes and weights, built once per BSDF.
struct BarbuleQuadratureRules {
  explicit BarbuleQuadratureRules(const BarbuleQuadrature& quadrature);
  int offsetNodeCount;
  std::vector<FloatLanes> offsetNodes, offsetWeights;  // in groups of four lanes
  std::vector<float> thetaNodes, thetaWeights;
  int lobeShareNodes;
};

// omega_i and what depends on it alone.
struct BarbuleIncident {
  Vec3 w;
  InPlaneDirection plane;
  LitArc arc;
  float coverage = 0.0f;
  bool scatters = false;  // above the vane with part of the arc lit
};

// The lobe choice: the probability of T, decided from omega_i alone (0 when the caller carries
// pass-through itself), and the TRT share s(h) of the scattering samples at offset h, linear
// between `nodes` offsets spread evenly over the lit arc.
struct BarbuleLobeChoice {
  float transmission = 1.0f;
  float hMin = 0.0f, nodeSpacing = 0.0f;
  int nodes = 0;
  std::array<float, kMaxLobeShareNodes> trtShare{};

  float trtShareAt(float h) const;
  // Integral of s(h) dh over [lo, hi] within the lit arc.
  float trtShareIntegral(float lo, float hi) const;
};

// What sampling needs at a point, from omega_i alone: its quantities and the lobe choice.
struct BarbuleScattering {
  BarbuleIncident in;
  BarbuleLobeChoice choice;
};

// omega_o, and what R, TRT and the sampling density share for the pair (omega_i, omega_o): the
// offsets lit from both, and the half vector with its in-plane direction, its normal in the
// ellipse's frame and whether that normal reflects between the two (within thetaD, lit from both).
struct BarbuleOutgoing {
  Vec3 w;
  OffsetInterval common;
  Vec3 m;
  InPlaneDirection mPlane;
  Vec2 mLocal;
  bool reflects = false;
};

// The model's two non-delta lobes f(omega_i, omega_o), without any cosine.
struct BarbuleLobes {
  Spectrum reflection, trt;
};

// The sampling density of omega_o, by the lobe that draws it.
struct BarbuleLobeDensities {
  float reflection = 0.0f, trt = 0.0f;
  float total() const { return reflection + trt; }
};

// A direction drawn from omega_i (the paper's Algorithm 1, docs/model.md §8).
struct BarbuleSample {
  enum class Lobe { T, R, TRT };
  Lobe lobe = Lobe::T;
  Vec3 wo;
  LitArc woArc;
  // For an R sample, the share of visible longitudinal angles it was drawn with
  // (MirrorVisibleAngles::visibleFraction()); negative otherwise.
  float mirrorVisible = -1.0f;
  // With weights: the density of wo (the mixture's, when asked for; T's probability for T) and
  // the drawing lobe's f |cos theta_o| over that lobe's density (T's pass-through weight for T).
  float pdf = 0.0f;
  Spectrum weight;
};

class BarbulePointModel {
 public:
  // `own` is the point's cross-section where it has one of its own, `shared` the BSDF's otherwise;
  // the film is the cortex over `params`' layer stack `layerStack`.
  BarbulePointModel(std::optional<BarbuleCrossSection> own, const BarbuleCrossSection& shared,
                    const BarbuleParameters& params, float thicknessUm, const Wavelengths& wl,
                    const BarbuleQuadratureRules& rules, int layerStack = 0);
  BarbulePointModel(const BarbulePointModel&) = delete;
  BarbulePointModel& operator=(const BarbulePointModel&) = delete;

  const BarbuleCrossSection& geometry() const { return geometry_; }
  LitArc litArc(const Vec3& w) const { return geometry_.litArc(inPlane(w).dir); }

  BarbuleIncident incident(const Vec3& w) const { return incident(w, litArc(w)); }
  BarbuleIncident incident(const Vec3& w, const LitArc& arc) const;
  // omega_i's quantities and the lobe choice.
  BarbuleScattering scattering(const Vec3& omegaI, bool passThroughByCaller) const;
  // omega_o, whose lit arc is `arc`, with what the pair shares.
  BarbuleOutgoing outgoing(const BarbuleIncident& in, const Vec3& wo, const LitArc& arc) const;

  BarbuleLobes lobes(const BarbuleIncident& in, const BarbuleOutgoing& out) const;
  // f(omega_i, omega_o) |cos theta_o|, both lobes.
  Spectrum value(const BarbuleIncident& in, const BarbuleOutgoing& out) const;
  // The fraction of light along omega_i passing between the barbules.
  float transmission(const BarbuleIncident& in) const;
  // What emitter candidates are chosen by: R exactly (what varies fast across an area light) and
  // a bound of TRT, times |cos theta_o|; none of TRT's quadrature.
  Spectrum resamplingTarget(const BarbuleIncident& in, const Vec3& wo, const LitArc& woArc) const;

  // The density of omega_o by lobe; `mirrorVisible` as in BarbuleSample for an R sample just
  // drawn, negative otherwise, and `drawnOffset` the offset of its point where the normal does
  // not fix the point (a superellipse), NaN otherwise.
  BarbuleLobeDensities densities(const BarbuleScattering& s, const BarbuleOutgoing& out, float mirrorVisible = -1.0f,
                                 float drawnOffset = std::numeric_limits<float>::quiet_NaN()) const;
  // Draws omega_o. With `weights`, also its weight and (`withPdf`) the mixture's density; without
  // `withPdf` an R sample's weight comes in closed form and a TRT sample's from its own density.
  std::optional<BarbuleSample> sample(const BarbuleScattering& s, float uComponent, Vec2 u, bool weights,
                                      bool withPdf) const;

 private:
  // The same as outgoing without the common lit interval: what R needs.
  BarbuleOutgoing mirrorGeometry(const BarbuleIncident& in, const Vec3& wo, const LitArc& arc) const;
  Spectrum reflection(const BarbuleIncident& in, const BarbuleOutgoing& out) const;
  Spectrum trt(const BarbuleIncident& in, const BarbuleOutgoing& out) const;
  // The TRT integrand's mean over the longitudinal angles at one offset node (thetaNodes > 1),
  // per wavelength.
  Spectrum trtLongitudinalMean(float projectedIn, float projectedOut, float inY, float outY) const;
  BarbuleLobeChoice lobeChoice(const BarbuleIncident& in, bool passThroughByCaller) const;
  static float trtDensity(const BarbuleScattering& s, const BarbuleOutgoing& out);

  std::optional<BarbuleCrossSection> own_;
  const BarbuleCrossSection& geometry_;
  const BarbuleQuadratureRules& rules_;
  BarbuleFilm film_;
  Spectrum melanin_;
};

// Fraction of light along w passing through the gaps of `geometry`.
float gapTransmission(const BarbuleCrossSection& geometry, const Vec3& w);

}  // namespace columba
