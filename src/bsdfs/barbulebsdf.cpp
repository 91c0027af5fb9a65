/*! plugin bsdf barbulebsdf barbulebsdfev
The barbule BSDF of rock dove neck feathers (Huang et al. 2022): a vane of parallel barbules with elliptical cross-sections, coated by a thin keratin film over melanin. Its lobes are R, the specular reflection off the film with thin-film interference (a microfacet lobe whose normals come from the cross-section's curvature), TRT, light through the film reflected by the melanin layer and back out, and T, light straight through the gaps between barbules (a pass-through). The frame has z along the vane normal and y along the barbule axis. `barbulebsdf` takes the camera side as the model's incident direction, as a BSDF-sampled path tracer needs; `barbulebsdfev` takes the light's, as the paper's emitter-sampled visualisations do, and returns what an imaging scatterometer records, f · |cos θ_camera|. The [model](../model.md) page derives the lobes.

On a feather whose file gives per-vertex values of `H`, `mu` or `height`, those win over a constant given here (with a warning naming the line); a texture given here wins over them.
Mitsuba 3: not in Mitsuba 3.
| parameter | type | default | meaning | Mitsuba 3 |
| preset | string | — | a named set of shape parameters and film thickness (`dove-green`, `dove-purple`); parameters given beside it override its values | not in Mitsuba 3 |
| b | float or texture | 0.25 | the cross-section's semi-axis along the vane normal (the one across is 1); positive | not in Mitsuba 3 |
| phi_0 | float | −0.37 | the start of the reflective arc: a normal angle, in radians, in the cross-section's frame | not in Mitsuba 3 |
| phi_1 | float | 2.64 | the end of the reflective arc; φ₁ − φ₀ lies in (0, π] or is at least 2π | not in Mitsuba 3 |
| mu | float or texture | −0.35 | the tilt of the cross-section about the barbule axis, in radians | not in Mitsuba 3 |
| H | float or texture | 1.25 | the barbule spacing, in units of the across semi-axis; positive | not in Mitsuba 3 |
| height | float or texture | 0.6 | the keratin film's thickness in micrometres; not negative (a value that looks like nanometres warns) | not in Mitsuba 3 |
| film_ior | float, string or spectrum | `keratin` | the film's index: a number, a named index, `keratin`, or a spectrum of the index against wavelength; it must exceed `ext_ior` | not in Mitsuba 3 |
| film_cauchy_a | float | — | the film's index as a Cauchy law a + b/λ², instead of `film_ior` | not in Mitsuba 3 |
| film_cauchy_b | float | 0 | the Cauchy law's b (λ in nanometres) | not in Mitsuba 3 |
| ext_ior | float or string | `air` (1.000277) | the surrounding medium's constant index | not in Mitsuba 3 |
| melanin | spectrum or float | measured table | the melanin layer's intensity reflectance against wavelength, 0 to 1; by default the embedded measured table | not in Mitsuba 3 |
*/
#include "bsdfs/barbulebsdf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include "barbule/mirror_visibility.h"
#include "barbule/normals.h"
#include "core/gauss_legendre.h"
#include "core/sampling.h"
#include "optics/melanin.h"
#include "optics/thin_film.h"

// Normalisation. Write r = lit width / (H |cos gamma_i|) for omega_i's coverage, A = cos(theta_i)
// cos(gamma_i - phi - mu) for the in-plane projected area of a normal, and G for the in-plane
// visibility (lit from omega_i and seen from omega_o).
//
// R: f_R = I_R(omega_i . m) D(m) G S(omega_i) S(omega_o) / (4 |omega_i . n| |omega_o . n|) with
// m the half vector and S the longitudinal shadowing of LongitudinalDensity. With
// d omega_o = 4 (omega_i . m) dm and D dm = D_phi D_theta dphi dtheta,
//   integral of f_R |cos theta_o| d omega_o
//     = (1 / |omega_i . n|) integral of D_phi [integral of D_theta (omega_i . m)+ S(omega_i) ...
//       dtheta] dphi,
// where the inner integral is A times a mean over theta (that is what S(omega_i) normalises), and
// integral of rho cos(gamma_i - phi - mu) G_i dphi = lit width (dh = rho cos(...) dphi). With
// |omega_i . n| = cos(theta_i) cos(gamma_i), the lobe's albedo is r times the mean, over the
// visible normals (h uniform on the lit width, theta | phi proportional to omega_i . m), of
// I_R S(omega_o) G_o. The coverage is inside D and G: no separate factor r.
//
// TRT: f_TRT = rho / pi with rho = (1 / (H |cos gamma_i|)) integral over the offsets lit from both
// directions of E_theta[I_TRT] dh = r times the mean of I_TRT G_o over the visible normals. For a
// fixed normal, the directions on its front side carry integral of |cos theta_o| / pi = 1, so the
// albedo is at most r max(I_TRT).
//
// Sampling, as the paper's Algorithm 1: T against scattering with probabilities proportional to t and
// r (<I_R> + <I_TRT>), estimated from omega_i alone (scattering always when the caller carries T
// itself, BSDFContext::passThroughByCaller, as the direct integrator does); for scattering an offset h uniform on the
// lit width, then R or TRT in proportion to their weights at h (s(h), the TRT share, is linear between a few offsets,
// so its integral below has a closed form and pdf() reproduces everything exactly):
//   R:   theta by inverse CDF at h's normal (a visible normal), restricted to the angles whose
//        mirror direction no neighbour masks (MirrorVisibleAngles: a share V(h) of theta's
//        density), and the mirror direction; its density is
//        (1 - s(h_m)) p(phi) p(theta | phi) / V(h_m) / cos(theta_m) / (4 omega_i . m), h_m the
//        offset of the half vector's normal. Where every angle at h is masked the sample is lost;
//   TRT: a cosine-weighted direction about h's normal (theta_m = 0) flipped to its front; its
//        density is (integral of s over the offsets lit from both / lit width) |cos theta_o| / pi;
//   T:   -wi with weight t / P(T).
// Both scattering densities carry the factor 1 - P(T). TRT samples whose point is not visible from
// omega_o are rejected, as are R samples that rounding puts just outside the visible angles. A
// sample reports the mixture density of what is returned (an R sample's with the share V it was
// drawn with); its weight is the drawing lobe's value over that lobe's density (see sampleAt), and
// for the evaluation twin eval / pdf.

namespace columba {

namespace {

// Lower bound on R's and TRT's shares at each node, and on the scattering weight relative to r:
// keeps every lobe reachable where an estimate happens to be near zero.
constexpr float kMinLobeShare = 0.01f;
// The longitudinal normal angles are small enough for cosSinOfSmallAngle.
static_assert(kBarbuleThetaD <= kSmallAngleLimit);

void makeRule(int n, std::vector<float>& nodes, std::vector<float>& weights) {
  GaussLegendreRule rule = gaussLegendre(n);
  nodes.assign(rule.nodes.begin(), rule.nodes.end());
  weights.assign(rule.weights.begin(), rule.weights.end());
}

// Light crossing the vane from below follows the same line as light along -w from above, so it
// meets the same gaps: transmission is symmetric under w -> -w. (Mirroring only z would pick a
// different line through the tilted cross-sections.)
Vec3 towardAbove(const Vec3& w) { return w.z < 0.0f ? -w : w; }

// A shape's value of a parameter at the point; a tilt or thickness of exactly 0 stands for the
// BSDF's own, as in the original implementation (docs/feather-ply.md).
std::optional<float> shapeValueUnlessZero(const BSDFContext& ctx, SurfaceAttributeKey key) {
  std::optional<float> v = ctx.attribute(key);
  return v && *v != 0.0f ? v : std::nullopt;
}

// A texture's value, `fallback` where it is not a finite number.
float finiteOr(float value, float fallback) { return std::isfinite(value) ? value : fallback; }

// Fraction of light along w passing through the gaps.
float gapTransmission(const BarbuleCrossSection& geometry, const Vec3& w) {
  InPlaneDirection p = inPlane(towardAbove(w));
  if (!(p.cosTheta > 0.0f)) return 1.0f;
  return 1.0f - geometry.coverage(geometry.litArc(p.dir), p.dir);
}

}  // namespace

// The model at one shading point, what a call needs besides the directions: the cross-section
// with the point's own tilt and spacing, and the film (with the point's thickness) and melanin at
// the path's wavelengths. Built in place: `geometry` may refer to `overridden`.
struct BarbuleBSDF::PointModel {
  PointModel(const BarbuleBSDF& bsdf, const BSDFContext& ctx, const Wavelengths& wl);
  PointModel(const PointModel&) = delete;
  PointModel& operator=(const PointModel&) = delete;

  std::optional<BarbuleCrossSection> overridden;
  const BarbuleCrossSection& geometry;
  FreeStandingFilm film;
  Spectrum melanin;
};

// The model's incident direction and what depends on it alone.
struct BarbuleBSDF::Incident {
  Vec3 w;
  InPlaneDirection plane;
  LitArc arc;
  float coverage = 0.0f;
  bool scatters = false;  // above the vane with part of the arc lit
};

// The pass-through weight of omega_i: its coverage's complement, already known when it scatters.
float BarbuleBSDF::transmission(const BarbuleCrossSection& geometry, const Incident& in) {
  return in.scatters ? 1.0f - in.coverage : gapTransmission(geometry, in.w);
}

// The lobe choice: the probability of T, decided from omega_i alone (0 when the caller carries
// pass-through itself), and the TRT share s(h) of the scattering samples at offset h, linear
// between `nodes` offsets spread evenly over the lit arc.
struct BarbuleBSDF::LobeChoice {
  float transmission = 1.0f;
  float hMin = 0.0f, nodeSpacing = 0.0f;
  int nodes = 0;
  std::array<float, kMaxLobeShareNodes> trtShare{};

  float trtShareAt(float h) const;
  // Integral of s(h) dh over [lo, hi] within the lit arc.
  float trtShareIntegral(float lo, float hi) const;
};

float BarbuleBSDF::LobeChoice::trtShareAt(float h) const {
  float x = clampf((h - hMin) / nodeSpacing, 0.0f, float(nodes - 1));
  int i = std::min(int(x), nodes - 2);
  float f = x - float(i);
  return trtShare[i] + f * (trtShare[i + 1] - trtShare[i]);
}

float BarbuleBSDF::LobeChoice::trtShareIntegral(float lo, float hi) const {
  // The trapezoid rule on each linear piece overlapping [lo, hi]: exact.
  float sum = 0.0f;
  for (int i = 0; i + 1 < nodes; ++i) {
    float a = std::max(lo, hMin + float(i) * nodeSpacing), b = std::min(hi, hMin + float(i + 1) * nodeSpacing);
    if (b > a) sum += 0.5f * (b - a) * (trtShareAt(a) + trtShareAt(b));
  }
  return sum;
}

// omega_o, and what R, TRT and the sampling density share for the pair (omega_i, omega_o): the
// offsets lit from both, and the half vector with its in-plane direction, its normal in the
// ellipse's frame and whether that normal reflects between the two (within thetaD, lit from both).
struct BarbuleBSDF::Outgoing {
  Vec3 w;
  OffsetInterval common;
  Vec3 m;
  InPlaneDirection mPlane;
  Vec2 mLocal;
  bool reflects = false;
};

BarbuleBSDF::Outgoing BarbuleBSDF::outgoing(const PointModel& point, const Incident& in, const Vec3& wo,
                                            const LitArc& arc) const {
  Outgoing out = mirrorGeometry(point, in, wo, arc);
  if (in.scatters) out.common = point.geometry.commonOffsets(in.arc, arc);
  return out;
}

BarbuleBSDF::Outgoing BarbuleBSDF::mirrorGeometry(const PointModel& point, const Incident& in, const Vec3& wo,
                                                  const LitArc& arc) const {
  Outgoing out;
  out.w = wo;
  if (!in.scatters) return out;  // no lobe and no density reads the rest
  const BarbuleCrossSection& geometry = point.geometry;
  Vec3 sum = in.w + wo;
  float lengthSqr = lengthSquared(sum);
  if (!(lengthSqr > 0.0f)) return out;
  out.m = sum / std::sqrt(lengthSqr);
  if (std::abs(out.m.y) >= kSinBarbuleThetaD) return out;
  out.mPlane = inPlane(out.m);
  out.mLocal = geometry.toLocal(out.mPlane.dir);
  out.reflects = geometry.isLit(in.arc, out.mLocal) && geometry.isLit(arc, out.mLocal);
  return out;
}

BarbuleBSDF::BarbuleBSDF(const BarbuleParameters& params, Role role, BarbuleQuadrature quadrature)
    : params_(params),
      role_(role),
      geometry_(params.b, params.phi0, params.phi1, params.mu, params.H),
      offsetNodeCount_(quadrature.offsetNodes) {
  GaussLegendreRule offsets = gaussLegendre(quadrature.offsetNodes);
  offsetNodes_ = laneGroups(offsets.nodes);
  offsetWeights_ = laneGroups(offsets.weights);
  makeRule(quadrature.thetaNodes, thetaNodes_, thetaWeights_);
  lobeShareNodes_ = std::clamp(quadrature.lobeShareNodes, 2, kMaxLobeShareNodes);
}

BarbuleBSDF::PointModel::PointModel(const BarbuleBSDF& bsdf, const BSDFContext& ctx, const Wavelengths& wl)
    : overridden(bsdf.overriddenGeometry(ctx)),
      geometry(overridden ? *overridden : bsdf.geometry_),
      film(bsdf.params_.filmIOR, bsdf.params_.extIOR, bsdf.cortexThickness(ctx), wl) {
  const std::optional<SpectralDistribution>& own = bsdf.params_.melanin;
  for (int i = 0; i < kSpectrumSamples; ++i) melanin[i] = own ? own->eval(wl[i]) : melaninReflectance(wl[i]);
}

float BarbuleBSDF::cortexThickness(const BSDFContext& ctx) const {
  const float height = textures_.height.isTextured()
                           ? finiteOr(textures_.height.eval(ctx.point), 0.0f)
                           : shapeValueUnlessZero(ctx, kCortexThicknessAttribute).value_or(params_.height);
  return std::max(height, 0.0f);
}

std::optional<BarbuleCrossSection> BarbuleBSDF::overriddenGeometry(const BSDFContext& ctx) const {
  // A texture wins over the shape's value; a spacing below contact acts as contact.
  std::optional<float> mu = textures_.mu.isTextured() ? finiteOr(textures_.mu.eval(ctx.point), params_.mu)
                                                      : shapeValueUnlessZero(ctx, kBarbuleTiltAttribute);
  std::optional<float> H = textures_.H.isTextured() ? finiteOr(textures_.H.eval(ctx.point), params_.H)
                                                    : ctx.attribute(kBarbuleSpacingAttribute);
  if (textures_.b.isTextured()) {
    // A semi-axis that is not positive (or not a number) is taken as a thin one.
    constexpr float kThinnest = 1e-3f;
    const float b = textures_.b.eval(ctx.point);
    return BarbuleCrossSection(b > kThinnest ? b : kThinnest, params_.phi0, params_.phi1, mu.value_or(params_.mu),
                               H.value_or(params_.H));
  }
  if (!mu && !H) return std::nullopt;
  return geometry_.withTiltAndSpacing(mu.value_or(params_.mu), H.value_or(params_.H));
}

BarbuleBSDF::Incident BarbuleBSDF::incident(const PointModel& point, const Vec3& w) const {
  return incident(point, w, point.geometry.litArc(inPlane(w).dir));
}

BarbuleBSDF::Incident BarbuleBSDF::incident(const PointModel& point, const Vec3& w, const LitArc& arc) const {
  Incident in;
  in.w = w;
  in.plane = inPlane(w);
  in.arc = arc;  // also below the vane, where it is the arc seen by an outgoing direction
  if (!(w.z > 0.0f) || !(in.plane.cosTheta > 0.0f)) return in;
  in.coverage = point.geometry.coverage(in.arc, in.plane.dir);
  in.scatters = in.arc.width() > 0.0f && in.coverage > 0.0f;
  return in;
}

Spectrum BarbuleBSDF::reflection(const PointModel& point, const Incident& in, const Outgoing& out) const {
  if (!out.reflects) return Spectrum(0.0f);
  const Vec3& m = out.m;
  const InPlaneDirection& mp = out.mPlane;
  float ndf = barbuleNDF(point.geometry, out.mLocal, mp.cosTheta);
  float shadowIn = longitudinalShadowing(inPlaneProjection(in.w, mp.dir), in.w.y);
  float shadowOut = longitudinalShadowing(inPlaneProjection(out.w, mp.dir), out.w.y);
  float scale = ndf * shadowIn * shadowOut / (4.0f * std::abs(in.w.z) * std::abs(out.w.z));
  FreeStandingFilm::Reflectance film = point.film.reflectance(dot(in.w, m));
  return (0.5f * scale) * (film.s + film.p);
}

Spectrum BarbuleBSDF::trt(const PointModel& point, const Incident& in, const Outgoing& out) const {
  const BarbuleCrossSection& geometry = point.geometry;
  const OffsetInterval& common = out.common;
  const Vec3& omegaO = out.w;
  float length = common.length();
  if (!(length > 0.0f)) return Spectrum(0.0f);

  // I_TRT / R_m = 1/2 (T_s(in) T_s(out) + T_p(in) T_p(out)): the film's transmittanceProduct.
  // Offsets through the circle angle psi (h = halfWidth sin(psi), dh = halfWidth cos(psi) dpsi):
  // the normal turns smoothly with psi, also where the interval ends at a silhouette of omega_i.
  // The geometry of four offset nodes is evaluated at once, in SIMD lanes.
  float halfWidth = in.arc.halfWidth;
  FloatLanes psiEnds = asinLanes(FloatLanes{common.lo, common.hi, 0.0f, 0.0f} / halfWidth);
  float psiLo = psiEnds[0], psiSpan = psiEnds[1] - psiEnds[0];
  // Weights of the mean over [lo, hi] in h.
  float weightScale = halfWidth * psiSpan / length;
  Spectrum sum;
  for (size_t group = 0; group < offsetNodes_.size(); ++group) {
    FloatLanes sinPsi, cosPsi;
    sinCosWithinQuarterTurn(psiLo + offsetNodes_[group] * psiSpan, sinPsi, cosPsi);
    FloatLanes weight = offsetWeights_[group] * (weightScale * cosPsi);
    Vec2Lanes n = geometry.worldNormalsAtAngles(in.arc, sinPsi, cosPsi);
    FloatLanes projectedIn = inPlaneProjection(in.w, n), projectedOut = inPlaneProjection(omegaO, n);
    if (thetaNodes_.size() == 1) {
      // One longitudinal node at the mean angle (|theta| <= thetaD).
      FloatLanes c, sn;
      cosSinOfSmallAngle(meanLongitudinalAngles(projectedIn, in.w.y), c, sn);
      FloatLanes cosIn = projectedIn * c + in.w.y * sn, cosOut = absLanes(projectedOut * c + omegaO.y * sn);
      // The film at the nodes in lanes (padding lanes weigh 0), summed over them per wavelength.
      sum += point.film.weightedTransmittanceProducts(weight, cosIn, cosOut);
      continue;
    }
    int lanes = std::min(kLaneCount, offsetNodeCount_ - int(group) * kLaneCount);
    for (int j = 0; j < lanes; ++j)
      sum += weight[j] * trtLongitudinalMean(point, projectedIn[j], projectedOut[j], in.w.y, omegaO.y);
  }
  // f_TRT = rho / pi, rho = (1 / (H |cos gamma_i|)) * length * mean; |cos gamma_i| = |z| / cos(theta_i).
  float scale = length * in.plane.cosTheta / (kPi * geometry.spacing() * std::abs(in.w.z));
  return scale * point.melanin * sum;
}

Spectrum BarbuleBSDF::trtLongitudinalMean(const PointModel& point, float projectedIn, float projectedOut, float inY,
                                          float outY) const {
  // Longitudinal mean with density proportional to omega_i . m over the range facing omega_i,
  // split where omega_o . m changes sign (a kink of the integrand); Gauss-Legendre on each piece.
  LongitudinalDensity longitudinal(projectedIn, inY);
  float pieces[3] = {longitudinal.thetaMin(), longitudinal.thetaMax(), longitudinal.thetaMax()};
  int pieceCount = 1;
  if (outY != 0.0f) {
    float kink = std::atan(-projectedOut / outY);
    if (kink > pieces[0] && kink < pieces[1]) {
      pieces[1] = kink;
      pieceCount = 2;
    }
  }
  Spectrum inner;
  float norm = 0.0f;
  for (int piece = 0; piece < pieceCount; ++piece) {
    float lo = pieces[piece], span = pieces[piece + 1] - lo;
    for (size_t j = 0; j < thetaNodes_.size(); ++j) {
      float theta = lo + thetaNodes_[j] * span;
      float c = std::cos(theta), sn = std::sin(theta);
      float cosIn = projectedIn * c + inY * sn, cosOut = std::abs(projectedOut * c + outY * sn);
      float w = thetaWeights_[j] * span * std::max(cosIn, 0.0f);
      if (!(w > 0.0f)) continue;
      inner += w * point.film.transmittanceProduct(cosIn, cosOut);
      norm += w;
    }
  }
  return norm > 0.0f ? inner / norm : Spectrum();
}

BarbuleBSDF::Lobes BarbuleBSDF::evalLobesForPair(const PointModel& point, const Incident& in,
                                                 const Outgoing& out) const {
  if (!in.scatters || out.w.z == 0.0f) return {};
  return {reflection(point, in, out), trt(point, in, out)};
}

Spectrum BarbuleBSDF::resamplingTarget(const PointModel& point, const Incident& in, const Vec3& wo,
                                       const LitArc& woArc) const {
  if (!in.scatters || wo.z == 0.0f) return Spectrum(0.0f);
  // TRT at its bound: trt()'s scale with the film's transmittance products at 1 and the whole lit
  // width for the interval lit from both directions, positive wherever TRT is, at the cost of none
  // of its nodes and no common interval.
  float trtBound = in.arc.width() * in.plane.cosTheta / (kPi * point.geometry.spacing() * std::abs(in.w.z));
  return (reflection(point, in, mirrorGeometry(point, in, wo, woArc)) + trtBound * point.melanin) * std::abs(wo.z);
}

BarbuleBSDF::LobeChoice BarbuleBSDF::lobeChoice(const PointModel& point, const Incident& in,
                                                bool passThroughByCaller) const {
  LobeChoice choice;
  if (passThroughByCaller) choice.transmission = 0.0f;
  if (!in.scatters) return choice;
  const BarbuleCrossSection& geometry = point.geometry;
  // The lobes' weights at each node's normal (theta_m = 0), averaged over the wavelengths: I_R, and
  // R_m T^2 for TRT (the film's transmission on the way out taken as on the way in).
  choice.nodes = lobeShareNodes_;
  choice.hMin = in.arc.hMin;
  choice.nodeSpacing = in.arc.width() / float(choice.nodes - 1);
  float meanWeight = 0.0f;  // of R + TRT over the lit offsets: the trapezoid rule, as s(h) is linear
  // The nodes' normals, incidence cosines and lobe weights, four nodes at a time.
  for (int first = 0; first < choice.nodes; first += kLaneCount) {
    FloatLanes h;
    for (int j = 0; j < kLaneCount; ++j)
      h[j] = choice.hMin + float(std::min(first + j, choice.nodes - 1)) * choice.nodeSpacing;
    FloatLanes cosines = inPlaneProjection(in.w, geometry.worldNormalsAtOffsets(in.arc, h));
    FreeStandingFilm::Averages film = point.film.averagesOverWavelengths(cosines, point.melanin);
    for (int j = 0; j < kLaneCount && first + j < choice.nodes; ++j) {
      const int k = first + j;
      float weightR = film.reflectance[j], weightTRT = film.weightedTransmittanceSqr[j];
      float total = weightR + weightTRT;
      choice.trtShare[k] = total > 0.0f ? clampf(weightTRT / total, kMinLobeShare, 1.0f - kMinLobeShare) : 0.5f;
      bool end = k == 0 || k == choice.nodes - 1;
      meanWeight += (end ? 0.5f : 1.0f) * total / float(choice.nodes - 1);
    }
  }
  if (passThroughByCaller) return choice;
  float energyScatter = in.coverage * std::max(meanWeight, kMinLobeShare), energyT = 1.0f - in.coverage;
  choice.transmission = energyT / (energyT + energyScatter);
  return choice;
}

BarbuleBSDF::LobeDensities BarbuleBSDF::samplingPdfs(const PointModel& point, const Incident& in,
                                                     const LobeChoice& choice, const Outgoing& out,
                                                     float mirrorVisible) const {
  LobeDensities density;
  if (!in.scatters) return density;
  const float scattering = 1.0f - choice.transmission;
  if (out.reflects) {
    float cosHalf = dot(in.w, out.m);
    if (cosHalf > 0.0f) {
      float normalPdf =
          visibleNormalPdf(point.geometry, in.arc, in.w, in.plane.cosTheta, cosHalf, out.mPlane, out.mLocal);
      // An R sample reports the share it was drawn with. Recomputed at the half vector's normal
      // (equal to the sampled one up to rounding) the share is the same except where a cut lies
      // where a(theta) peaks: there it can jump from near 0 to 1 under a rounding change of the
      // normal, and dividing by the recomputed share gave single samples 10^4 times their due.
      float visible = mirrorVisible >= 0.0f ? mirrorVisible
                                            : MirrorVisibleAngles(point.geometry, out.mLocal, in.w).visibleFraction();
      float shareR = 1.0f - choice.trtShareAt(point.geometry.offsetOf(in.arc, out.mLocal));
      if (visible > 0.0f) density.reflection = scattering * shareR * normalPdf / visible / (4.0f * cosHalf);
    }
  }
  density.trt = trtSamplingPdf(in, choice, out);
  return density;
}

float BarbuleBSDF::trtSamplingPdf(const Incident& in, const LobeChoice& choice, const Outgoing& out) {
  if (!in.scatters) return 0.0f;
  // The offset uniform on the lit width and TRT's share there, then wo cosine-distributed.
  return (1.0f - choice.transmission) * choice.trtShareIntegral(out.common.lo, out.common.hi) / in.arc.width() *
         std::abs(out.w.z) * kInvPi;
}

Spectrum BarbuleBSDF::evalForPair(const PointModel& point, const Incident& in, const Outgoing& out) const {
  Lobes lobes = evalLobesForPair(point, in, out);
  return (lobes.reflection + lobes.trt) * std::abs(out.w.z);
}

Spectrum BarbuleBSDF::evalAt(const PointModel& point, const Incident& fromWi, const Vec3& wo,
                             const LitArc& woArc) const {
  if (role_ == Role::CameraIncident) return evalForPair(point, fromWi, outgoing(point, fromWi, wo, woArc));
  // The scatterometer's quantity: light from wo, the camera's cosine (wi), so that a visualiser
  // image is the power scattered per solid angle toward each camera direction.
  Incident fromWo = incident(point, wo, woArc);
  return evalForPair(point, fromWo, outgoing(point, fromWo, fromWi.w, fromWi.arc));
}

Spectrum BarbuleBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  PointModel point(*this, ctx, wl);
  LitArc wiArc = point.geometry.litArc(inPlane(wi).dir), woArc = point.geometry.litArc(inPlane(wo).dir);
  return evalAt(point, incident(point, wi, wiArc), wo, woArc);
}

BSDFEvalPdf BarbuleBSDF::evalPdfAt(const PointModel& point, const Incident& fromWi, const LobeChoice& choice,
                                   const Vec3& wo, const LitArc& woArc, float mirrorVisible) const {
  Outgoing out = outgoing(point, fromWi, wo, woArc);
  // With omega_i on the camera side, value and density share the pair's geometry.
  Spectrum value = role_ == Role::CameraIncident ? evalForPair(point, fromWi, out) : evalAt(point, fromWi, wo, woArc);
  return {value, samplingPdfs(point, fromWi, choice, out, mirrorVisible).total()};
}

float BarbuleBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return lobePdfs(ctx, wi, wo, wl).total();
}

BarbuleBSDF::LobeDensities BarbuleBSDF::lobePdfs(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo,
                                                 const Wavelengths& wl) const {
  PointModel point(*this, ctx, wl);
  Incident in = incident(point, wi);
  if (!in.scatters) return {};
  Outgoing out = outgoing(point, in, wo, point.geometry.litArc(inPlane(wo).dir));
  return samplingPdfs(point, in, lobeChoice(point, in, ctx.passThroughByCaller), out);
}

std::optional<BSDFSample> BarbuleBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                              float uComponent, Vec2 u) const {
  PointModel point(*this, ctx, wl);
  Incident in = incident(point, wi);
  return sampleAt(point, in, lobeChoice(point, in, ctx.passThroughByCaller), uComponent, u);
}

BSDFVertexQueries BarbuleBSDF::queryVertex(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                           const BSDFVertexRequest& request) const {
  PointModel point(*this, ctx, wl);
  Incident in = incident(point, wi);
  bool needsChoice = request.sample || (request.woLightCount > 0 && request.lightPdf);
  LobeChoice choice = needsChoice ? lobeChoice(point, in, ctx.passThroughByCaller) : LobeChoice{};
  BSDFVertexQueries q;
  auto evaluateTowardLight = [&](int k, const LitArc& woArc) {
    const Vec3& wo = request.woLights[k];
    request.toLights[k] =
        request.lightPdf ? evalPdfAt(point, in, choice, wo, woArc) : BSDFEvalPdf{evalAt(point, in, wo, woArc), 0.0f};
  };
  // With a chooser and cheap targets: the targets toward every candidate, the full value (TRT's
  // quadrature) and density toward the chosen one only. Otherwise the values are the targets.
  const bool cheapTargets = request.chooseLight && hasCheapResamplingTargets();
  auto litArcToward = [&](int k) { return point.geometry.litArc(inPlane(request.woLights[k]).dir); };
  for (int k = 0; k < request.woLightCount; ++k) {
    if (cheapTargets)
      request.toLights[k] = {resamplingTarget(point, in, request.woLights[k], litArcToward(k)), 0.0f};
    else
      evaluateTowardLight(k, litArcToward(k));
  }
  if (request.chooseLight) {
    const int chosen = request.chooseLight->choose(request.toLights, request.woLightCount);
    if (cheapTargets && chosen >= 0) evaluateTowardLight(chosen, litArcToward(chosen));  // its arc again: cheap
  }
  if (request.sample) q.sampled = sampleAt(point, in, choice, request.uComponent, request.u, request.samplePdf);
  if (request.passThrough) q.passThrough = Spectrum(transmission(point.geometry, in));
  return q;
}

std::optional<BSDFSample> BarbuleBSDF::sampleAt(const PointModel& point, const Incident& in, const LobeChoice& choice,
                                                float uComponent, Vec2 u, bool withPdf) const {
  const BarbuleCrossSection& geometry = point.geometry;
  const Vec3& wi = in.w;
  BSDFSample bs;
  if (uComponent < choice.transmission) {
    float t = transmission(geometry, in);
    if (!(t > 0.0f)) return std::nullopt;
    bs.wo = -wi;
    bs.pdf = choice.transmission;
    bs.weight = Spectrum(t / choice.transmission);
    bs.delta = bs.passThrough = true;
    return bs;
  }
  if (!in.scatters) return std::nullopt;  // only T was left, and the caller carries it

  // The scattering point: an offset uniform on the lit width, from what uComponent has left.
  float uOffset = clampf((uComponent - choice.transmission) / (1.0f - choice.transmission), 0.0f, 1.0f);
  float h = in.arc.hMin + uOffset * in.arc.width();
  float shareR = 1.0f - choice.trtShareAt(h);
  const Vec2 localNormal = geometry.normalAt(geometry.pointAt(in.arc, h));
  const bool reflected = u.x < shareR;
  float mirrorVisible = -1.0f;  // the share of visible angles an R sample is drawn with
  Vec3 m;                       // an R sample's normal
  Vec2 mWorld;                  // and its in-plane part
  if (reflected) {
    // theta among the angles whose mirror direction a neighbour does not mask: the others could
    // only be rejected below.
    MirrorVisibleAngles angles(geometry, localNormal, wi);
    mirrorVisible = angles.visibleFraction();
    if (!(mirrorVisible > 0.0f)) return std::nullopt;
    AngleCosSin theta = angles.sample(u.y);
    mWorld = angles.worldNormal();
    m = barbuleNormal(mWorld, theta.cosTheta, theta.sinTheta);
    bs.wo = reflect(wi, m);
  } else {
    Vec3 facing = barbuleNormal(geometry.toWorld(localNormal), 1.0f, 0.0f);
    // What u.x has left within the TRT share drives the direction with u.y.
    Vec3 w = sampleCosineHemisphere(Vec2(clampf((u.x - shareR) / (1.0f - shareR), 0.0f, 1.0f), u.y));
    bs.wo = dot(w, facing) >= 0.0f ? w : -w;
  }
  // The scattering point must be visible from wo.
  LitArc woArc = geometry.litArc(inPlane(bs.wo).dir);
  if (!geometry.isLit(woArc, localNormal)) return std::nullopt;

  if (role_ == Role::LightIncident) {
    BSDFEvalPdf f = evalPdfAt(point, in, choice, bs.wo, woArc, mirrorVisible);
    bs.pdf = f.pdf;
    if (!(bs.pdf > 0.0f)) return std::nullopt;
    bs.weight = f.value / bs.pdf;
    return bs;
  }
  if (!withPdf && reflected) {
    // f_R |cos_o| / p_R in closed form, at the sampled normal m (docs/model.md section 8). With
    // A = omega_i's projection on m's in-plane normal, rho the radius of curvature and M the mass
    // of the longitudinal density ((A cos theta + B sin theta)+ over |theta| < thetaD),
    //   f_R |cos_o| = F D S_i S_o / (4 |cos_i|),  D = rho / (H 2 sin(thetaD) cos(theta_m)),
    //   S_i = 2 sin(thetaD) A / M  (longitudinalShadowing; S_o likewise for omega_o),
    //   p_R = s_R p_m / (v 4 omega_i . m),  p_m = rho A (omega_i . m) / (cos(theta_i) W M cos(theta_m))
    // (s_R the R share drawn with, v the visible share of angles, W the lit width, cos(theta_i)
    // the length of omega_i's in-plane part: visibleNormalPdf), so that
    //   f_R |cos_o| / p_R = F S_o v W cos(theta_i) / (H |cos_i| s_R):
    // rho, M, theta_m and the half vector cancel. The general path below computes each factor and
    // agrees with this within float rounding (BarbuleBSDF.AWeightWithoutPdfIsTheWeightWithIt).
    const float scattering = 1.0f - choice.transmission;
    float shadowOut = longitudinalShadowing(inPlaneProjection(bs.wo, mWorld), bs.wo.y);
    float scale = shadowOut * mirrorVisible * in.arc.width() * in.plane.cosTheta /
                  (geometry.spacing() * std::abs(wi.z) * scattering * shareR);
    FreeStandingFilm::Reflectance film = point.film.reflectance(dot(wi, m));
    if (!(scale > 0.0f) || bs.wo.z == 0.0f) return std::nullopt;
    bs.weight = (0.5f * scale) * (film.s + film.p);
    return bs;
  }
  // Each lobe is estimated by the samples it draws: an R sample weighs f_R |cos| over R's density,
  // a TRT sample f_TRT |cos| over TRT's, and bs.pdf is their sum, the density of wo. For any
  // function g of wo, E[weight g] is then the integral of (f_R + f_TRT) |cos| g, so MIS weights
  // built from bs.pdf keep the estimate unbiased; an R sample needs no TRT quadrature. (With the
  // mixture's eval / pdf instead, simulation3's variance per sample was the same, 0.0950 against
  // 0.0954, and the time 9 % longer.)
  Outgoing out = outgoing(point, in, bs.wo, woArc);
  // Without the pdf, a TRT sample needs only its own lobe's density.
  LobeDensities density = withPdf ? samplingPdfs(point, in, choice, out, mirrorVisible)
                                  : LobeDensities{0.0f, trtSamplingPdf(in, choice, out)};
  bs.pdf = withPdf ? density.total() : 0.0f;
  const float lobeDensity = reflected ? density.reflection : density.trt;
  if (!(lobeDensity > 0.0f) || bs.wo.z == 0.0f) return std::nullopt;
  Spectrum value = reflected ? reflection(point, in, out) : trt(point, in, out);
  bs.weight = value * (std::abs(bs.wo.z) / lobeDensity);
  return bs;
}

Spectrum BarbuleBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths&) const {
  std::optional<BarbuleCrossSection> own = overriddenGeometry(ctx);
  return Spectrum(gapTransmission(own ? *own : geometry_, wi));
}

BarbuleBSDF::Lobes BarbuleBSDF::evalLobes(const BSDFContext& ctx, const Vec3& omegaI, const Vec3& omegaO,
                                          const Wavelengths& wl) const {
  PointModel point(*this, ctx, wl);
  Incident in = incident(point, omegaI);
  return evalLobesForPair(point, in, outgoing(point, in, omegaO, point.geometry.litArc(inPlane(omegaO).dir)));
}

float BarbuleBSDF::coverage(const BSDFContext& ctx, const Vec3& omegaI) const {
  std::optional<BarbuleCrossSection> own = overriddenGeometry(ctx);
  return 1.0f - gapTransmission(own ? *own : geometry_, omegaI);
}

namespace {

// A <float>, a <string> with a number, a named index or "keratin", or (`tabulated`) a <spectrum>
// of the index against wavelength.
RefractiveIndex readIOR(const Properties& props, const std::string& name, const std::string& defaultName,
                        bool tabulated) {
  if (props.has(name) && !props.isString(name)) {
    SpectralDistribution n = tabulated ? props.getSpectrum(name, 1.0f, SpectrumUse::Unbounded)
                                       : SpectralDistribution::constant(props.getFloat(name));
    if (!n.isConstant()) return RefractiveIndex::tabulated(std::move(n));
    float value = n.eval(kLambdaMin);
    if (!(value > 0.0f)) throw props.error(name, "the index of refraction must be positive");
    return RefractiveIndex::constant(value);
  }
  std::string text = props.getString(name, defaultName);
  std::optional<RefractiveIndex> ior = iorFromName(text);
  if (!ior)
    throw props.error(name, "unknown index of refraction '" + text +
                                "' (give a number, a named material such as 'air', or 'keratin')");
  return *ior;
}

BarbuleParameters readParameters(const Properties& props) {
  BarbuleParameters p;
  if (props.has("preset")) {
    std::string name = props.getString("preset");
    std::optional<BarbuleParameters> preset = barbulePreset(name);
    if (!preset) throw props.error("preset", "unknown preset '" + name + "' (known: " + barbulePresetNames() + ")");
    p = *preset;
  }
  p.b = props.getFloat("b", p.b);
  p.phi0 = props.getFloat("phi_0", p.phi0);
  p.phi1 = props.getFloat("phi_1", p.phi1);
  p.mu = props.getFloat("mu", p.mu);
  p.H = props.getFloat("H", p.H);
  p.height = props.getFloat("height", p.height);
  if (props.has("film_cauchy_a") || props.has("film_cauchy_b")) {
    if (props.has("film_ior"))
      throw props.error("film_ior", "give the film's index either as film_ior or as film_cauchy_a/film_cauchy_b");
    p.filmIOR = RefractiveIndex::cauchy(props.getFloat("film_cauchy_a"), props.getFloat("film_cauchy_b", 0.0f));
  } else {
    p.filmIOR = readIOR(props, "film_ior", "keratin", true);
  }
  RefractiveIndex ext = readIOR(props, "ext_ior", "air", false);
  if (!ext.isConstant()) throw props.error("ext_ior", "the surrounding medium needs a constant index");
  p.extIOR = ext.a;
  if (props.has("melanin")) p.melanin = props.getSpectrum("melanin", 0.0f, SpectrumUse::Unbounded);

  if (std::optional<BarbuleParameterProblem> problem = findProblem(p)) {
    bool cauchy = problem->parameter == "film_ior" && props.has("film_cauchy_a");
    throw props.error(cauchy ? "film_cauchy_a" : problem->parameter, problem->message);
  }
  if (std::optional<BarbuleParameterProblem> odd = findImplausibility(p))
    warn(props.locationOf(odd->parameter), "barbulebsdf, parameter '" + odd->parameter + "': " + odd->message);
  return p;
}

std::shared_ptr<Object> makeBarbule(const Properties& props, BarbuleBSDF::Role role) {
  auto bsdf = std::make_shared<BarbuleBSDF>(readParameters(props), role);
  const BarbuleParameters& p = bsdf->parameters();
  BarbuleTextures textures{readFloatParameter(props, "b", p.b), readFloatParameter(props, "mu", p.mu),
                           readFloatParameter(props, "H", p.H), readFloatParameter(props, "height", p.height)};
  bsdf->setSceneSources(std::make_shared<PerPointParameterSources>(
      props, "preset",
      std::initializer_list<PerPointParameterSources::Parameter>{
          {"H", kBarbuleSpacingAttribute, textures.H.isTextured()},
          {"mu", kBarbuleTiltAttribute, textures.mu.isTextured()},
          {"height", kCortexThicknessAttribute, textures.height.isTextured()}}));
  bsdf->setTextures(std::move(textures));
  return bsdf;
}

}  // namespace

std::shared_ptr<Object> makeBarbuleBSDF(const Properties& props) {
  return makeBarbule(props, BarbuleBSDF::Role::CameraIncident);
}

std::shared_ptr<Object> makeBarbuleBSDFEv(const Properties& props) {
  return makeBarbule(props, BarbuleBSDF::Role::LightIncident);
}

}  // namespace columba
