#include "barbule/point_model.h"

#include <algorithm>
#include <cmath>

#include "barbule/mirror_visibility.h"
#include "core/gauss_legendre.h"
#include "core/sampling.h"
#include "optics/melanin.h"

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

}  // namespace

float gapTransmission(const BarbuleCrossSection& geometry, const Vec3& w) {
  InPlaneDirection p = inPlane(towardAbove(w));
  if (!(p.cosTheta > 0.0f)) return 1.0f;
  return 1.0f - geometry.coverage(geometry.litArc(p.dir), p.dir);
}

BarbuleQuadratureRules::BarbuleQuadratureRules(const BarbuleQuadrature& quadrature)
    : offsetNodeCount(quadrature.offsetNodes) {
  GaussLegendreRule offsets = gaussLegendre(quadrature.offsetNodes);
  offsetNodes = laneGroups(offsets.nodes);
  offsetWeights = laneGroups(offsets.weights);
  makeRule(quadrature.thetaNodes, thetaNodes, thetaWeights);
  lobeShareNodes = std::clamp(quadrature.lobeShareNodes, 2, kMaxLobeShareNodes);
}

BarbulePointModel::BarbulePointModel(std::optional<BarbuleCrossSection> own, const BarbuleCrossSection& shared,
                                     const BarbuleParameters& params, float thicknessUm, const Wavelengths& wl,
                                     const BarbuleQuadratureRules& rules, int layerStack)
    : own_(std::move(own)),
      geometry_(own_ ? *own_ : shared),
      rules_(rules),
      film_(params, thicknessUm, wl, layerStack) {
  for (int i = 0; i < kSpectrumSamples; ++i)
    melanin_[i] = params.melanin ? params.melanin->eval(wl[i]) : melaninReflectance(wl[i]);
}

BarbuleScattering BarbulePointModel::scattering(const Vec3& omegaI, bool passThroughByCaller) const {
  BarbuleScattering s;
  s.in = incident(omegaI);
  s.choice = lobeChoice(s.in, passThroughByCaller);
  return s;
}

// The pass-through weight of omega_i: its coverage's complement, already known when it scatters.
float BarbulePointModel::transmission(const BarbuleIncident& in) const {
  return in.scatters ? 1.0f - in.coverage : gapTransmission(geometry_, in.w);
}

BarbuleLobes BarbulePointModel::lobes(const BarbuleIncident& in, const BarbuleOutgoing& out) const {
  if (!in.scatters || out.w.z == 0.0f) return {};
  return {reflection(in, out), trt(in, out)};
}

Spectrum BarbulePointModel::value(const BarbuleIncident& in, const BarbuleOutgoing& out) const {
  BarbuleLobes l = lobes(in, out);
  return (l.reflection + l.trt) * std::abs(out.w.z);
}

float BarbuleLobeChoice::trtShareAt(float h) const {
  float x = clampf((h - hMin) / nodeSpacing, 0.0f, float(nodes - 1));
  int i = std::min(int(x), nodes - 2);
  float f = x - float(i);
  return trtShare[i] + f * (trtShare[i + 1] - trtShare[i]);
}

float BarbuleLobeChoice::trtShareIntegral(float lo, float hi) const {
  // The trapezoid rule on each linear piece overlapping [lo, hi]: exact.
  float sum = 0.0f;
  for (int i = 0; i + 1 < nodes; ++i) {
    float a = std::max(lo, hMin + float(i) * nodeSpacing), b = std::min(hi, hMin + float(i + 1) * nodeSpacing);
    if (b > a) sum += 0.5f * (b - a) * (trtShareAt(a) + trtShareAt(b));
  }
  return sum;
}

BarbuleIncident BarbulePointModel::incident(const Vec3& w, const LitArc& arc) const {
  BarbuleIncident in;
  in.w = w;
  in.plane = inPlane(w);
  in.arc = arc;  // also below the vane, where it is the arc seen by an outgoing direction
  if (!(w.z > 0.0f) || !(in.plane.cosTheta > 0.0f)) return in;
  in.coverage = geometry_.coverage(in.arc, in.plane.dir);
  in.scatters = in.arc.width() > 0.0f && in.coverage > 0.0f;
  return in;
}

BarbuleOutgoing BarbulePointModel::outgoing(const BarbuleIncident& in, const Vec3& wo, const LitArc& arc) const {
  BarbuleOutgoing out = mirrorGeometry(in, wo, arc);
  if (in.scatters) out.common = geometry_.commonOffsets(in.arc, arc);
  return out;
}

BarbuleOutgoing BarbulePointModel::mirrorGeometry(const BarbuleIncident& in, const Vec3& wo, const LitArc& arc) const {
  BarbuleOutgoing out;
  out.w = wo;
  if (!in.scatters) return out;  // no lobe and no density reads the rest
  const BarbuleCrossSection& geometry = geometry_;
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

Spectrum BarbulePointModel::reflection(const BarbuleIncident& in, const BarbuleOutgoing& out) const {
  if (!out.reflects) return Spectrum(0.0f);
  const Vec3& m = out.m;
  const InPlaneDirection& mp = out.mPlane;
  float ndf = barbuleNDF(geometry_, out.mLocal, mp.cosTheta);
  float shadowIn = longitudinalShadowing(inPlaneProjection(in.w, mp.dir), in.w.y);
  float shadowOut = longitudinalShadowing(inPlaneProjection(out.w, mp.dir), out.w.y);
  float scale = ndf * shadowIn * shadowOut / (4.0f * std::abs(in.w.z) * std::abs(out.w.z));
  FreeStandingFilm::Reflectance film = film_.reflectance(dot(in.w, m));
  return (0.5f * scale) * (film.s + film.p);
}

Spectrum BarbulePointModel::trt(const BarbuleIncident& in, const BarbuleOutgoing& out) const {
  const BarbuleCrossSection& geometry = geometry_;
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
  for (size_t group = 0; group < rules_.offsetNodes.size(); ++group) {
    FloatLanes sinPsi, cosPsi;
    sinCosWithinQuarterTurn(psiLo + rules_.offsetNodes[group] * psiSpan, sinPsi, cosPsi);
    FloatLanes weight = rules_.offsetWeights[group] * (weightScale * cosPsi);
    Vec2Lanes n = geometry.worldNormalsAtAngles(in.arc, sinPsi, cosPsi);
    FloatLanes projectedIn = inPlaneProjection(in.w, n), projectedOut = inPlaneProjection(omegaO, n);
    if (rules_.thetaNodes.size() == 1) {
      // One longitudinal node at the mean angle (|theta| <= thetaD).
      FloatLanes c, sn;
      cosSinOfSmallAngle(meanLongitudinalAngles(projectedIn, in.w.y), c, sn);
      FloatLanes cosIn = projectedIn * c + in.w.y * sn, cosOut = absLanes(projectedOut * c + omegaO.y * sn);
      // The film at the nodes in lanes (padding lanes weigh 0), summed over them per wavelength.
      sum += film_.weightedTransmittanceProducts(weight, cosIn, cosOut);
      continue;
    }
    int lanes = std::min(kLaneCount, rules_.offsetNodeCount - int(group) * kLaneCount);
    for (int j = 0; j < lanes; ++j)
      sum += weight[j] * trtLongitudinalMean(projectedIn[j], projectedOut[j], in.w.y, omegaO.y);
  }
  // f_TRT = rho / pi, rho = (1 / (H |cos gamma_i|)) * length * mean; |cos gamma_i| = |z| / cos(theta_i).
  float scale = length * in.plane.cosTheta / (kPi * geometry.spacing() * std::abs(in.w.z));
  return scale * melanin_ * sum;
}

Spectrum BarbulePointModel::trtLongitudinalMean(float projectedIn, float projectedOut, float inY, float outY) const {
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
    for (size_t j = 0; j < rules_.thetaNodes.size(); ++j) {
      float theta = lo + rules_.thetaNodes[j] * span;
      float c = std::cos(theta), sn = std::sin(theta);
      float cosIn = projectedIn * c + inY * sn, cosOut = std::abs(projectedOut * c + outY * sn);
      float w = rules_.thetaWeights[j] * span * std::max(cosIn, 0.0f);
      if (!(w > 0.0f)) continue;
      inner += w * film_.transmittanceProduct(cosIn, cosOut);
      norm += w;
    }
  }
  return norm > 0.0f ? inner / norm : Spectrum();
}

Spectrum BarbulePointModel::resamplingTarget(const BarbuleIncident& in, const Vec3& wo, const LitArc& woArc) const {
  if (!in.scatters || wo.z == 0.0f) return Spectrum(0.0f);
  // TRT at its bound: trt()'s scale with the film's transmittance products at 1 and the whole lit
  // width for the interval lit from both directions, positive wherever TRT is, at the cost of none
  // of its nodes and no common interval.
  float trtBound = in.arc.width() * in.plane.cosTheta / (kPi * geometry_.spacing() * std::abs(in.w.z));
  return (reflection(in, mirrorGeometry(in, wo, woArc)) + trtBound * melanin_) * std::abs(wo.z);
}

BarbuleLobeChoice BarbulePointModel::lobeChoice(const BarbuleIncident& in, bool passThroughByCaller) const {
  BarbuleLobeChoice choice;
  if (passThroughByCaller) choice.transmission = 0.0f;
  if (!in.scatters) return choice;
  const BarbuleCrossSection& geometry = geometry_;
  // The lobes' weights at each node's normal (theta_m = 0), averaged over the wavelengths: I_R, and
  // R_m T^2 for TRT (the film's transmission on the way out taken as on the way in).
  choice.nodes = rules_.lobeShareNodes;
  choice.hMin = in.arc.hMin;
  choice.nodeSpacing = in.arc.width() / float(choice.nodes - 1);
  float meanWeight = 0.0f;  // of R + TRT over the lit offsets: the trapezoid rule, as s(h) is linear
  // The nodes' normals, incidence cosines and lobe weights, four nodes at a time.
  for (int first = 0; first < choice.nodes; first += kLaneCount) {
    FloatLanes h;
    for (int j = 0; j < kLaneCount; ++j)
      h[j] = choice.hMin + float(std::min(first + j, choice.nodes - 1)) * choice.nodeSpacing;
    FloatLanes cosines = inPlaneProjection(in.w, geometry.worldNormalsAtOffsets(in.arc, h));
    FreeStandingFilm::Averages film = film_.averagesOverWavelengths(cosines, melanin_);
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

BarbuleLobeDensities BarbulePointModel::densities(const BarbuleScattering& s, const BarbuleOutgoing& out,
                                                  float mirrorVisible, float drawnOffset) const {
  const BarbuleIncident& in = s.in;
  const BarbuleLobeChoice& choice = s.choice;
  BarbuleLobeDensities density;
  if (!in.scatters) return density;
  const float scattering = 1.0f - choice.transmission;
  if (out.reflects) {
    float cosHalf = dot(in.w, out.m);
    if (cosHalf > 0.0f) {
      float normalPdf = visibleNormalPdf(geometry_, in.arc, in.w, in.plane.cosTheta, cosHalf, out.mPlane, out.mLocal);
      // An R sample reports the share it was drawn with. Recomputed at the half vector's normal
      // (equal to the sampled one up to rounding) the share is the same except where a cut lies
      // where a(theta) peaks: there it can jump from near 0 to 1 under a rounding change of the
      // normal, and dividing by the recomputed share gave single samples 10^4 times their due.
      float visible =
          mirrorVisible >= 0.0f ? mirrorVisible : MirrorVisibleAngles(geometry_, out.mLocal, in.w).visibleFraction();
      float offset = std::isnan(drawnOffset) ? geometry_.offsetOf(in.arc, out.mLocal) : drawnOffset;
      float shareR = 1.0f - choice.trtShareAt(offset);
      if (visible > 0.0f) density.reflection = scattering * shareR * normalPdf / visible / (4.0f * cosHalf);
    }
  }
  density.trt = trtDensity(s, out);
  return density;
}

float BarbulePointModel::trtDensity(const BarbuleScattering& s, const BarbuleOutgoing& out) {
  const BarbuleIncident& in = s.in;
  const BarbuleLobeChoice& choice = s.choice;
  if (!in.scatters) return 0.0f;
  // The offset uniform on the lit width and TRT's share there, then wo cosine-distributed.
  return (1.0f - choice.transmission) * choice.trtShareIntegral(out.common.lo, out.common.hi) / in.arc.width() *
         std::abs(out.w.z) * kInvPi;
}

std::optional<BarbuleSample> BarbulePointModel::sample(const BarbuleScattering& s, float uComponent, Vec2 u,
                                                       bool weights, bool withPdf) const {
  const BarbuleIncident& in = s.in;
  const BarbuleLobeChoice& choice = s.choice;
  const BarbuleCrossSection& geometry = geometry_;
  const Vec3& wi = in.w;
  BarbuleSample bs;
  if (uComponent < choice.transmission) {
    float t = transmission(in);
    if (!(t > 0.0f)) return std::nullopt;
    bs.wo = -wi;
    bs.pdf = choice.transmission;
    bs.weight = Spectrum(t / choice.transmission);
    return bs;
  }
  if (!in.scatters) return std::nullopt;  // only T was left, and the caller carries it

  // The scattering point: an offset uniform on the lit width, from what uComponent has left.
  float uOffset = clampf((uComponent - choice.transmission) / (1.0f - choice.transmission), 0.0f, 1.0f);
  float h = in.arc.hMin + uOffset * in.arc.width();
  float shareR = 1.0f - choice.trtShareAt(h);
  const Vec2 point = geometry.pointAt(in.arc, h), localNormal = geometry.normalAt(point);
  // On a superellipse's flat side the normal, known to float precision, does not fix the point
  // (docs/model.md, "Cross-sections beyond the ellipse"): the drawn point stands wherever the point
  // matters. The ellipse recovers it from the normal, as it always has (its images unchanged).
  const std::optional<Vec2> drawnPoint = geometry.isEllipse() ? std::nullopt : std::optional<Vec2>(point);
  const bool reflected = u.x < shareR;
  bs.lobe = reflected ? BarbuleSample::Lobe::R : BarbuleSample::Lobe::TRT;
  Vec3 m;       // an R sample's normal
  Vec2 mWorld;  // and its in-plane part
  if (reflected) {
    // theta among the angles whose mirror direction a neighbour does not mask: the others could
    // only be rejected below.
    MirrorVisibleAngles angles(geometry, localNormal, wi, drawnPoint);
    bs.mirrorVisible = angles.visibleFraction();
    if (!(bs.mirrorVisible > 0.0f)) return std::nullopt;
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
  bs.woArc = geometry.litArc(inPlane(bs.wo).dir);
  if (!(drawnPoint ? geometry.isLitAt(bs.woArc, *drawnPoint, localNormal) : geometry.isLit(bs.woArc, localNormal)))
    return std::nullopt;
  if (!weights) return bs;
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
    float scale = shadowOut * bs.mirrorVisible * in.arc.width() * in.plane.cosTheta /
                  (geometry.spacing() * std::abs(wi.z) * scattering * shareR);
    FreeStandingFilm::Reflectance film = film_.reflectance(dot(wi, m));
    if (!(scale > 0.0f) || bs.wo.z == 0.0f) return std::nullopt;
    bs.weight = (0.5f * scale) * (film.s + film.p);
    return bs;
  }
  // Each lobe is estimated by the samples it draws: an R sample weighs f_R |cos| over R's density,
  // a TRT sample f_TRT |cos| over TRT's, and bs.pdf is their sum, the density of wo. For any
  // function g of wo, E[weight g] is then the integral of (f_R + f_TRT) |cos| g, so MIS weights
  // built from bs.pdf keep the estimate unbiased; an R sample needs no TRT quadrature (the
  // mixture's eval / pdf costs time for no less variance: docs/performance.md).
  BarbuleOutgoing out = outgoing(in, bs.wo, bs.woArc);
  // The drawn point of an R sample is lit from both directions, whichever point its normal gives.
  if (reflected && drawnPoint && out.mPlane.cosTheta > 0.0f) out.reflects = true;
  // Without the pdf, a TRT sample needs only its own lobe's density.
  BarbuleLobeDensities density =
      withPdf
          ? densities(s, out, bs.mirrorVisible, reflected && drawnPoint ? h : std::numeric_limits<float>::quiet_NaN())
          : BarbuleLobeDensities{0.0f, trtDensity(s, out)};
  bs.pdf = withPdf ? density.total() : 0.0f;
  const float lobeDensity = reflected ? density.reflection : density.trt;
  if (!(lobeDensity > 0.0f) || bs.wo.z == 0.0f) return std::nullopt;
  Spectrum value = reflected ? reflection(in, out) : trt(in, out);
  bs.weight = value * (std::abs(bs.wo.z) / lobeDensity);
  return bs;
}

}  // namespace columba
