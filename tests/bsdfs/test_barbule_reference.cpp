// The production thin film and barbule BSDF against the plain double-precision reference of
// reference_thin_film.h and reference_barbule.h, over random parameter sets and direction pairs
// (fixed seeds). Each bound is a named constant saying where it comes from; each was set a small
// factor above the largest error measured, and the *Detects* tests show that a 1 % error in the
// film's phase or in TRT would exceed it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>
#include "barbule/cross_section.h"
#include "barbule/normals.h"
#include "bsdfs/barbulebsdf.h"
#include "core/rng.h"
#include "optics/melanin.h"
#include "optics/thin_film.h"
#include "support/reference_barbule.h"
#include "support/reference_thin_film.h"

using namespace columba;
namespace ref = columba::reference;

namespace {

// --- Bounds -----------------------------------------------------------------------------------
// Measured maxima (GCC 12 -O3, x86-64 with AVX2) are in the comments; each bound is a few times
// the measurement and far below what a 1 % error in TRT, R or the film's phase produces (the
// *Detect* tests, and the second half of TRTWithAFineQuadratureMatches).
//
// The production film works in float. Its phase, up to ~140 rad for a 5 um film, is good to a few
// 1e-7 of itself; near grazing incidence the reflectance and transmittance change so fast with the
// phase (resonances of width ~ the incidence cosine) that this alone makes errors of several %.
// So film values are judged by a backward error: the production value must be the Airy sum at a
// phase within kPhaseRounding of the true one, up to an amplitude error below a fraction of the
// value's scale:  |production - reference| <= kPhaseRounding |d reference / d ln(phase)|
// + amplitude * scale. The scale is the unpolarised interference envelope for reflectances (near a
// fringe's zero the reflectance itself is arbitrarily small; near Brewster's angle so is the p
// envelope) and the value itself for transmittances. The tests assert the largest ratio of error to
// allowance is below 1.
constexpr double kPhaseRounding = 1e-6;
// FreeStandingFilm::reflectance per polarisation. Measured max ratio 0.37 (the error itself reaches
// 1.1e-3 of the envelope near grazing incidence, 4.5e-5 near normal incidence, for 5 um films).
constexpr double kFilmReflectanceAmplitude = 1e-5;
// FreeStandingFilm::transmittanceProduct and weightedTransmittanceProducts (both implementations).
// Measured max ratio 0.51 and 0.47.
constexpr double kFilmTransmittanceAmplitude = 1e-5;
// The double-precision general stack (thinFilmAmplitudes) against the reference: the same formula
// in the same precision. Measured 2.2e-16.
constexpr double kGeneralStackBound = 1e-12;

// R lobe, amplitude part relative to the lobe with the film at its envelope: float D and the
// longitudinal shadowing S (whose clipped mass, a difference of two cosines near 1, keeps about 5
// digits in float: 2.4e-5, see FastMathReference). With the rounding part below, measured max ratio
// 0.47 (at a pair near backscatter, omega_o ~ -omega_i: an error of 5.1e-4 of the envelope).
constexpr double kReflectionAmplitude = 1e-4;
// Coverage r = 1 - T: the error of the lit width r H |cos gamma| it stands for (r itself is that over
// the projected period, which vanishes at grazing azimuths), in across semi-axes. Measured 3.8e-7.
constexpr double kLitWidthBound = 2e-6;
// TRT is compared relative to its value, but values below kTRTFloor of its largest possible value
// R_m / pi (coverage 1, film transmission 1) relative to that floor: where the offsets lit from both
// directions are a sliver, their float ends decide a tiny value.
constexpr double kTRTFloor = 1e-3;
// The ends of the offsets lit from both directions (BarbuleCrossSection::commonOffsets), in across
// semi-axes. Production finds omega_o's lit ends along omega_i's offsets through pointAt, whose
// sqrt(a - h^2 / b^2) cancels where that end is omega_o's silhouette: about half the float digits
// are lost there. Measured 4.3e-4 (elsewhere ~1e-7).
constexpr double kCommonEndError = 1e-3;
// TRT with a converged quadrature (kFineQuadrature) against the adaptive reference, relative (to
// the floor below it), besides the ends' error above: float sums of 4096 terms. Measured max ratio
// of error to the two together 0.09.
constexpr double kFineTRTBound = 1e-4;
// TRT with the default quadrature (4 offset nodes, 1 longitudinal node at the mean angle), the
// same measure. BarbuleQuadrature documents "about 0.7 % on average and 3 % at worst" for the L1
// error over outgoing directions per incident direction; the same L1 measure over all pairs is
// bounded by kDefaultTRTL1Bound. Pointwise, leaving nearly along the barbule axis (omega_o . m
// changing sign within +-thetaD, where the exit transmission ~ (omega_o . m)^2 is far from linear in
// theta) one node at the mean angle is far off: measured max 0.93 (L1 7.6e-3).
constexpr double kDefaultTRTBound = 1.5, kDefaultTRTL1Bound = 1.5e-2;

// A converged TRT quadrature: 256 offset nodes x 16 longitudinal nodes.
const BarbuleQuadrature kFineQuadrature{256, 16, 1};

// Pairs whose half vector's normal lies this close to a jump of G (the lit arc's ends) or of D
// (|theta_m| = thetaD) are left out of the R comparison: there float and double may decide the
// jump differently.
constexpr double kPhiMarginSkip = 1e-4, kThetaMarginSkip = 1e-5;

// The R lobe's allowance: the film's phase; the cosines computed as float dot products of unit
// vectors, good to a few 1e-7 absolute (near grazing incidence on a facet, omega_o ~ -omega_i, the
// film and S change fast with them, and the half vector is a normalised sum of nearly opposite
// directions); and kReflectionAmplitude of the envelope.
constexpr double kCosineRounding = 1e-6;
double reflectionAllowance(const ref::BarbuleReference::Reflection& r, int k) {
  return kPhaseRounding * r.phaseSensitivity[k] + kCosineRounding * r.roundingSensitivity[k] +
         kReflectionAmplitude * r.envelope[k];
}

bool nearAJump(const ref::BarbuleReference::Reflection& r) {
  return std::abs(r.thetaMargin) < kThetaMarginSkip || (r.thetaMargin > 0.0 && r.phiMargin < kPhiMarginSkip);
}

// --- Random parameter sets within the valid ranges of findProblem -----------------------------

struct Case {
  BarbuleParameters params;
  ref::BarbuleModel model;
  float constantMelanin = -1.0f;  // < 0: the measured table
  std::string name;
};

float uniform(PCG32& rng, float lo, float hi) { return lo + (hi - lo) * rng.nextFloat(); }

Case makeCase(const BarbuleParameters& p, float constantMelanin, const std::string& name) {
  Case c;
  c.params = p;
  c.constantMelanin = constantMelanin;
  if (constantMelanin >= 0.0f) c.params.melanin = SpectralDistribution::constant(constantMelanin);
  c.name = name;
  c.model.b = p.b;
  c.model.phi0 = p.phi0;
  c.model.phi1 = p.phi1;
  c.model.mu = p.mu;
  c.model.H = p.H;
  c.model.heightUm = p.height;
  c.model.filmA = p.filmIOR.a;
  c.model.filmB = p.filmIOR.b;
  c.model.nOutside = p.extIOR;
  return c;
}

std::vector<Case> randomCases(int count, uint64_t seed) {
  std::vector<Case> cases;
  cases.push_back(makeCase(BarbuleParameters{}, -1.0f, "defaults"));
  cases.push_back(makeCase(*barbulePreset("dove-purple"), -1.0f, "dove-purple"));
  PCG32 rng(seed);
  while (int(cases.size()) < count) {
    BarbuleParameters p;
    p.b = uniform(rng, 0.1f, 0.8f);
    p.mu = uniform(rng, -1.0f, 1.0f);
    // Sometimes below the contact spacing, which the model raises H to.
    p.H = BarbuleCrossSection::contactSpacing(p.b, p.mu) * uniform(rng, 0.8f, 2.5f);
    p.phi0 = uniform(rng, -kPi, kPi);
    p.phi1 = rng.nextFloat() < 0.1f ? p.phi0 + 6.5f : p.phi0 + uniform(rng, 0.2f, kPi - 1e-3f);
    p.height = uniform(rng, 0.05f, 1.2f);
    if (rng.nextFloat() < 0.3f) {
      p.filmIOR = RefractiveIndex::cauchy(uniform(rng, 1.4f, 1.9f), uniform(rng, 0.0f, 12000.0f));
      p.extIOR = rng.nextFloat() < 0.5f ? 1.0f : 1.33f;
    }
    float melanin = rng.nextFloat() < 0.25f ? uniform(rng, 0.0f, 0.3f) : -1.0f;
    if (findProblem(p)) continue;
    cases.push_back(makeCase(p, melanin, "random " + std::to_string(cases.size())));
  }
  return cases;
}

std::vector<double> melaninAt(const Case& c, const Wavelengths& wl) {
  // The measured table is data, read through the production's lookup (its own test checks it
  // against the published file); the reference integrates it like any other R_m.
  std::vector<double> m(kSpectrumSamples);
  for (int k = 0; k < kSpectrumSamples; ++k)
    m[k] = c.constantMelanin >= 0.0f ? c.constantMelanin : melaninReflectance(wl[k]);
  return m;
}

Wavelengths randomWavelengths(PCG32& rng) {
  return Wavelengths::fixed({uniform(rng, kLambdaMin, kLambdaMax), uniform(rng, kLambdaMin, kLambdaMax),
                             uniform(rng, kLambdaMin, kLambdaMax), uniform(rng, kLambdaMin, kLambdaMax)});
}

std::vector<double> lambdasOf(const Wavelengths& wl) { return {wl[0], wl[1], wl[2], wl[3]}; }

Vec3 uniformSphere(PCG32& rng) {
  float z = 1.0f - 2.0f * rng.nextFloat(), phi = kTwoPi * rng.nextFloat();
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}
Vec3 upperHemisphere(PCG32& rng) {
  Vec3 w;
  do w = uniformSphere(rng);
  while (std::abs(w.z) < 1e-3f);
  return w.z < 0.0f ? -w : w;
}

ref::Direction toReference(const Vec3& w) { return {w.x, w.y, w.z}; }

// wo mirrored about a normal lit from wi (chosen with the reference's lit normals), so that many
// pairs meet the R lobe.
Vec3 mirroredAboutALitNormal(PCG32& rng, const ref::BarbuleReference& model, double mu, const Vec3& wi) {
  std::vector<ref::AngleInterval> lit = model.litNormals(std::atan2(double(wi.x), double(wi.z)));
  double total = 0.0;
  for (const ref::AngleInterval& piece : lit) total += piece.hi - piece.lo;
  double phi = std::atan2(double(wi.x), double(wi.z)) - mu + (rng.nextDouble() - 0.5) * M_PI;  // none lit: any
  double u = rng.nextDouble() * total;
  for (const ref::AngleInterval& piece : lit) {
    if (u <= piece.hi - piece.lo) {
      phi = piece.lo + u;
      break;
    }
    u -= piece.hi - piece.lo;
  }
  double phiWorld = phi + mu, theta = (2.0 * rng.nextDouble() - 1.0) * ref::kThetaD;
  double m[3] = {std::cos(theta) * std::sin(phiWorld), std::sin(theta), std::cos(theta) * std::cos(phiWorld)};
  double d = wi.x * m[0] + wi.y * m[1] + wi.z * m[2];
  Vec3 wo(float(2 * d * m[0] - wi.x), float(2 * d * m[1] - wi.y), float(2 * d * m[2] - wi.z));
  return normalize(wo);
}

// --- Reference values of the sample pairs, computed once for all tests -------------------------

struct Pair {
  int caseIndex;
  Vec3 wi, wo;
  Wavelengths wl;
  std::vector<double> melanin;
  ref::BarbuleReference::Reflection reflection, reflectionReversed;  // (wi, wo) and (wo, wi)
  bool hasTRT = false;  // TRT is compared on half the pairs (its reference is the costly part)
  double coverageI = 0.0, coverageO = 0.0;
};

struct Samples {
  std::vector<Case> cases;
  std::vector<Pair> pairs;
};

constexpr int kCaseCount = 24, kPairsPerCase = 48;

const Samples& samples() {
  static const Samples all = [] {
    Samples s;
    s.cases = randomCases(kCaseCount, 2022);
    PCG32 rng(1729);
    for (int c = 0; c < int(s.cases.size()); ++c) {
      ref::BarbuleReference model(s.cases[c].model);
      for (int j = 0; j < kPairsPerCase; ++j) {
        Pair p;
        p.caseIndex = c;
        p.wi = upperHemisphere(rng);
        // Half the pairs anywhere on the sphere, half mirrored about a normal (the R lobe).
        p.wo = j % 2 == 0 ? uniformSphere(rng) : mirroredAboutALitNormal(rng, model, s.cases[c].model.mu, p.wi);
        if (std::abs(p.wo.z) < 1e-3f) p.wo = upperHemisphere(rng);
        p.wl = randomWavelengths(rng);
        p.melanin = melaninAt(s.cases[c], p.wl);
        std::vector<double> lambdas = lambdasOf(p.wl);
        ref::Direction wi = toReference(p.wi), wo = toReference(p.wo);
        p.reflection = model.reflection(wi, wo, lambdas);
        p.reflectionReversed = model.reflection(wo, wi, lambdas);
        p.hasTRT = j % 4 < 2;
        p.coverageI = model.coverage(wi);
        p.coverageO = model.coverage(wo);
        s.pairs.push_back(p);
      }
    }
    return s;
  }();
  return all;
}

// The TRT references of the pairs that have them (others empty), (wi, wo) and (wo, wi), computed
// on first use: only the TRT and eval tests need them.
struct TRTReference {
  ref::BarbuleReference::TRT forward, reversed;
};
const std::vector<TRTReference>& trtReferences() {
  static const std::vector<TRTReference> all = [] {
    const Samples& s = samples();
    std::vector<TRTReference> out(s.pairs.size());
    for (size_t i = 0; i < s.pairs.size(); ++i) {
      const Pair& p = s.pairs[i];
      if (!p.hasTRT) continue;
      ref::BarbuleReference model(s.cases[p.caseIndex].model);
      std::vector<double> lambdas = lambdasOf(p.wl);
      out[i].forward = model.trt(toReference(p.wi), toReference(p.wo), lambdas, p.melanin);
      out[i].reversed = model.trt(toReference(p.wo), toReference(p.wi), lambdas, p.melanin);
    }
    return out;
  }();
  return all;
}

// Values of TRT below this are judged against it (kTRTFloor).
double trtFloor(double melanin) { return kTRTFloor * melanin / M_PI; }

// The converged TRT's allowance: kFineTRTBound of the value (at least of the floor), and the ends
// of the offsets lit from both directions off by kCommonEndError.
double trtAllowance(const ref::BarbuleReference::TRT& t, double melanin, int k) {
  return kFineTRTBound * std::max(t.value[k], trtFloor(melanin)) + kCommonEndError * t.endDensity[k];
}

struct ErrorStats {
  double max = 0.0, sum = 0.0;
  long count = 0;
  std::string worst;
  void add(double e, const std::string& where) {
    if (e > max) {
      max = e;
      worst = where;
    }
    sum += e;
    ++count;
  }
  double mean() const { return count ? sum / count : 0.0; }
};

std::string describe(const Samples& s, const Pair& p) {
  char text[256];
  std::snprintf(text, sizeof text, "%s wi (%.4f %.4f %.4f) wo (%.4f %.4f %.4f)", s.cases[p.caseIndex].name.c_str(),
                p.wi.x, p.wi.y, p.wi.z, p.wo.x, p.wo.y, p.wo.z);
  return text;
}

// TRT of every pair from a production BSDF per case, against the reference: the largest error and
// the L1 error over the pairs (weighted by |cos theta_o|, as the lobe's albedo weighs it).
struct TRTErrors {
  ErrorStats pointwise;   // relative (to the floor below it)
  ErrorStats ratio;       // over trtAllowance
  ErrorStats beyondEnds;  // relative, beyond what the ends' error allows
  double l1 = 0.0;
};
TRTErrors trtErrors(const BarbuleQuadrature& quadrature, double productionScale = 1.0) {
  const Samples& s = samples();
  std::vector<BarbuleBSDF> bsdfs;
  for (const Case& c : s.cases) bsdfs.emplace_back(c.params, BarbuleBSDF::Role::CameraIncident, quadrature);
  TRTErrors e;
  double difference = 0.0, total = 0.0;
  for (size_t i = 0; i < s.pairs.size(); ++i) {
    const Pair& p = s.pairs[i];
    if (!p.hasTRT) continue;
    const ref::BarbuleReference::TRT& reference = trtReferences()[i].forward;
    Spectrum f = bsdfs[p.caseIndex].evalLobes(BSDFContext{}, p.wi, p.wo, p.wl).trt;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      double expected = reference.value[k], floor = trtFloor(p.melanin[k]);
      if (!(floor > 0.0)) continue;
      double error = std::abs(productionScale * f[k] - expected);
      e.pointwise.add(error / std::max(expected, floor), describe(s, p));
      e.ratio.add(error / trtAllowance(reference, p.melanin[k], k), describe(s, p));
      e.beyondEnds.add(std::max(0.0, error - kCommonEndError * reference.endDensity[k]) / std::max(expected, floor),
                       describe(s, p));
      difference += error * std::abs(p.wo.z);
      total += expected * std::abs(p.wo.z);
    }
  }
  e.l1 = difference / total;
  return e;
}

}  // namespace

// --- The reference checked on its own -----------------------------------------------------------

TEST(ThinFilmReference, AirySumEqualsThePartialWaveSeries) {
  // The closed form against the explicit sum of multiply reflected waves, and R + T = 1 for a
  // lossless stack, including total internal reflection in the film or at the substrate.
  PCG32 rng(5);
  for (int i = 0; i < 2000; ++i) {
    double n1 = 1.0 + rng.nextDouble(), n2 = 1.0 + 1.5 * rng.nextDouble(), n3 = 1.0 + rng.nextDouble();
    // Near grazing incidence |r21 r23| -> 1 and the series converges too slowly to sum.
    double c = 0.02 + 0.98 * rng.nextDouble(), d = 2.0 * rng.nextDouble(), lambda = 360.0 + 470.0 * rng.nextDouble();
    ref::AiryFilm f = ref::airyFilm(c, n1, n2, n3, d, lambda);
    std::pair<ref::Complex, ref::Complex> series = ref::partialWaveSum(c, n1, n2, n3, d, lambda, 4000);
    EXPECT_LT(std::abs(f.rs - series.first), 1e-9) << n1 << " " << n2 << " " << n3 << " " << c;
    EXPECT_LT(std::abs(f.rp - series.second), 1e-9) << n1 << " " << n2 << " " << n3 << " " << c;
    EXPECT_NEAR(f.reflectanceS() + f.transmittanceS(), 1.0, 1e-12);
    EXPECT_NEAR(f.reflectanceP() + f.transmittanceP(), 1.0, 1e-12);
    ref::AiryFilm grazing = ref::airyFilm(1e-3 * c, n1, n2, n3, d, lambda);
    EXPECT_NEAR(grazing.reflectanceS() + grazing.transmittanceS(), 1.0, 1e-12);
    EXPECT_NEAR(grazing.reflectanceP() + grazing.transmittanceP(), 1.0, 1e-12);
  }
}

TEST(BarbuleReference, ReferenceIsSelfConsistentSlow) {
  // Lit width two ways (offsets of the ends; integral of rho cos dphi), the contact spacing
  // against sampled overlap, and the TRT integral against a finer one.
  for (const Case& c : randomCases(12, 99)) {
    ref::BarbuleReference model(c.model);
    for (double gamma = -1.5; gamma <= 1.5; gamma += 0.25)
      EXPECT_NEAR(model.litWidth(gamma), model.litWidthByIntegral(gamma), 1e-10) << c.name << " gamma " << gamma;
    // Just above the contact spacing no point of the neighbour at +H lies inside the central
    // ellipse; just below, some does.
    double Hc = ref::BarbuleReference::contactSpacing(c.model.b, c.model.mu);
    auto overlaps = [&](double H) {
      for (int j = 0; j < 20000; ++j) {
        double t = 2.0 * M_PI * j / 20000, u = c.model.b * std::cos(t), v = std::sin(t) + H * std::cos(c.model.mu);
        u += H * std::sin(c.model.mu);  // the neighbour in the central ellipse's own frame
        if ((u / c.model.b) * (u / c.model.b) + v * v < 1.0) return true;
      }
      return false;
    };
    EXPECT_FALSE(overlaps(Hc * (1.0 + 1e-9))) << c.name;
    EXPECT_TRUE(overlaps(Hc * (1.0 - 1e-3))) << c.name;
  }
  const std::vector<Case> cases = randomCases(4, 7);
  PCG32 rng(3);
  for (const Case& c : cases) {
    ref::BarbuleReference model(c.model), finer(c.model, 24, 1e-12);
    for (int i = 0; i < 6; ++i) {
      ref::Direction wi = toReference(upperHemisphere(rng)), wo = toReference(uniformSphere(rng));
      // The first pair leaves nearly along -t: omega_o . m changes sign within +-thetaD.
      if (i == 0) {
        wi = {0.3380, 0.9122, 0.2317};
        wo = {-0.0310, -0.9992, 0.0268};
      }
      std::vector<double> lambdas = {400.0, 500.0, 600.0, 700.0}, melanin(4, 0.05);
      ref::BarbuleReference::TRT a = model.trt(wi, wo, lambdas, melanin), b = finer.trt(wi, wo, lambdas, melanin);
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.value[k], b.value[k], 1e-6 * b.value[k] + 1e-12) << c.name << " " << i;
    }
  }
}

// --- Thin film ------------------------------------------------------------------------------------

namespace {

// Largest ratios of error to allowance (see kPhaseRounding), and the largest reflectance error
// as a fraction of the envelope.
struct FilmErrors {
  double reflectance = 0.0, transmittance = 0.0, weighted = 0.0, reflectanceOfEnvelope = 0.0;
};

// The production free-standing film against the reference over random films, angles and
// wavelengths; `phaseScale` perturbs the reference's phase (to show what a phase error costs).
FilmErrors filmErrors(double phaseScale) {
  PCG32 rng(11);
  FilmErrors e;
  const double h = 1e-6;  // step of the phase derivatives
  for (int i = 0; i < 3000; ++i) {
    RefractiveIndex film = RefractiveIndex::keratin();
    float nOut = 1.000277f;
    if (i % 3 == 1) {
      film = RefractiveIndex::cauchy(uniform(rng, 1.4f, 2.2f), uniform(rng, 0.0f, 12000.0f));
      nOut = i % 2 ? 1.0f : 1.33f;
    }
    // Up to 5 um (the implausibility threshold): phases to ~140 rad, the range the film's
    // reduction of sin^2 serves.
    float d = i % 10 == 0 ? 0.0f : uniform(rng, 0.0f, 5.0f);
    Wavelengths wl = randomWavelengths(rng);
    FreeStandingFilm production(film, nOut, d, wl);
    // Cosines down to the production's clamp, 1e-4: log-uniform half the time.
    auto randomCos = [&] {
      return std::max(1e-4f,
                      rng.nextFloat() < 0.5f ? std::pow(10.0f, uniform(rng, -4.0f, 0.0f)) : uniform(rng, 1e-4f, 1.0f));
    };
    float c = randomCos();
    FreeStandingFilm::Reflectance r = production.reflectance(c);
    float c1[4], c2[4], weight[4];
    for (int j = 0; j < 4; ++j) {
      c1[j] = randomCos();
      c2[j] = randomCos();
      weight[j] = rng.nextFloat();
    }
    auto product = production.transmittanceProduct(c1[0], c2[0]);
    FloatLanes w{weight[0], weight[1], weight[2], weight[3]}, l1{c1[0], c1[1], c1[2], c1[3]},
        l2{c2[0], c2[1], c2[2], c2[3]};
    auto portable = production.weightedTransmittanceProductsPortable(w, l1, l2);
    auto avx2 = hasAvx2() ? production.weightedTransmittanceProductsAvx2(w, l1, l2) : portable;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      double lambda = wl[k], n = film(wl[k]);
      auto airy = [&](double scale) { return ref::airyFilm(c, nOut, n, nOut, d, lambda, phaseScale * scale); };
      ref::AiryFilm a = airy(1.0), above = airy(1.0 + h), below = airy(1.0 - h);
      double envelope = ref::freeStandingReflectanceEnvelope(c, nOut, n);
      auto ratio = [&](double error, double sensitivity, double amplitude, double scale) {
        return error / (kPhaseRounding * sensitivity + amplitude * scale);
      };
      double errorS = std::abs(r.s[k] - a.reflectanceS()), errorP = std::abs(r.p[k] - a.reflectanceP());
      e.reflectanceOfEnvelope = std::max({e.reflectanceOfEnvelope, errorS / envelope, errorP / envelope});
      e.reflectance = std::max({e.reflectance,
                                ratio(errorS, std::abs(above.reflectanceS() - below.reflectanceS()) / (2 * h),
                                      kFilmReflectanceAmplitude, envelope),
                                ratio(errorP, std::abs(above.reflectanceP() - below.reflectanceP()) / (2 * h),
                                      kFilmReflectanceAmplitude, envelope)});
      auto transmittance = [&](float cos1, float cos2, double scale) {
        return ref::freeStandingTransmittanceProduct(cos1, cos2, nOut, n, d, lambda, phaseScale * scale);
      };
      double expected = transmittance(c1[0], c2[0], 1.0);
      double sensitivity =
          std::abs(transmittance(c1[0], c2[0], 1.0 + h) - transmittance(c1[0], c2[0], 1.0 - h)) / (2 * h);
      e.transmittance = std::max(
          e.transmittance, ratio(std::abs(product[k] - expected), sensitivity, kFilmTransmittanceAmplitude, expected));
      double sum = 0.0, sumSensitivity = 0.0;
      for (int j = 0; j < 4; ++j) {
        sum += weight[j] * transmittance(c1[j], c2[j], 1.0);
        sumSensitivity +=
            weight[j] * std::abs(transmittance(c1[j], c2[j], 1.0 + h) - transmittance(c1[j], c2[j], 1.0 - h)) / (2 * h);
      }
      for (float value : {portable[k], avx2[k]})
        e.weighted =
            std::max(e.weighted, ratio(std::abs(value - sum), sumSensitivity, kFilmTransmittanceAmplitude, sum));
    }
  }
  return e;
}

}  // namespace

TEST(ThinFilmReference, FreeStandingFilmMatchesTheAirySum) {
  FilmErrors e = filmErrors(1.0);
  std::printf(
      "free-standing film vs reference, error over allowance: reflectance %.2f (error %.2e of the "
      "envelope), transmittance product %.2f, weighted products %.2f (AVX2 %s)\n",
      e.reflectance, e.reflectanceOfEnvelope, e.transmittance, e.weighted, hasAvx2() ? "yes" : "no");
  EXPECT_LT(e.reflectance, 1.0);
  EXPECT_LT(e.transmittance, 1.0);
  EXPECT_LT(e.weighted, 1.0);
}

TEST(ThinFilmReference, BoundsDetectAOnePercentPhaseError) {
  // A film whose phase were 1 % off would exceed the allowance many times over.
  FilmErrors e = filmErrors(1.01);
  std::printf("with a 1 %% phase error, error over allowance: reflectance %.2e, transmittance %.2e\n", e.reflectance,
              e.transmittance);
  EXPECT_GT(e.reflectance, 100.0);
  EXPECT_GT(e.transmittance, 100.0);
  EXPECT_GT(e.weighted, 100.0);
}

TEST(ThinFilmReference, GeneralStackMatchesTheReference) {
  // thinFilmAmplitudes / Reflectance / Transmittance for any real indices, total internal
  // reflection included.
  PCG32 rng(17);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    double n1 = 1.0 + rng.nextDouble(), n2 = 1.0 + 1.5 * rng.nextDouble(), n3 = 1.0 + rng.nextDouble();
    double c = rng.nextDouble(), d = 3.0 * rng.nextDouble(), lambda = 360.0 + 470.0 * rng.nextDouble();
    ThinFilmAmplitudes p = thinFilmAmplitudes(c, n1, n2, n3, d, lambda);
    ref::AiryFilm r = ref::airyFilm(c, n1, n2, n3, d, lambda);
    worst = std::max({worst, std::abs(p.rs - r.rs), std::abs(p.rp - r.rp), std::abs(p.ts - r.ts), std::abs(p.tp - r.tp),
                      std::abs(thinFilmReflectance(c, n1, n2, n3, d, lambda) - r.reflectance()),
                      std::abs(thinFilmTransmittance(c, n1, n2, n3, d, lambda) - r.transmittance())});
  }
  std::printf("general stack vs reference: max difference %.2e\n", worst);
  EXPECT_LT(worst, kGeneralStackBound);
}

// --- Barbule BSDF ---------------------------------------------------------------------------------

TEST(BarbuleReference, CoverageAndPassThroughMatchSlow) {
  const Samples& s = samples();
  std::vector<BarbuleBSDF> bsdfs;
  for (const Case& c : s.cases) bsdfs.emplace_back(c.params);
  ErrorStats stats;
  const Wavelengths wl = Wavelengths::fixed({450, 520, 600, 680});
  for (const Pair& p : s.pairs) {
    const BarbuleBSDF& bsdf = bsdfs[p.caseIndex];
    ref::BarbuleReference model(s.cases[p.caseIndex].model);
    for (const auto& [w, expected] : {std::pair{p.wi, p.coverageI}, std::pair{p.wo, p.coverageO}}) {
      // The projected period H |cos gamma| of the line through the layer (-w from below).
      double period = model.spacing() * std::abs(w.z) / std::hypot(double(w.x), double(w.z));
      stats.add(std::abs(bsdf.coverage(BSDFContext{}, w) - expected) * period, describe(s, p));
      stats.add(std::abs(bsdf.passThrough(BSDFContext{}, w, wl)[0] - (1.0 - expected)) * period, describe(s, p));
    }
  }
  std::printf("coverage vs reference: max error of the lit width %.2e (%s)\n", stats.max, stats.worst.c_str());
  EXPECT_LT(stats.max, kLitWidthBound) << stats.worst;
}

TEST(BarbuleReference, OffsetsLitFromBothDirectionsMatchSlow) {
  // BarbuleCrossSection::commonOffsets, the interval TRT integrates over (and its sampling density
  // weighs), against the reference's lit normals intersected.
  const Samples& s = samples();
  ErrorStats stats;
  for (const Pair& p : s.pairs) {
    const BarbuleParameters& b = s.cases[p.caseIndex].params;
    BarbuleCrossSection geometry(b.b, b.phi0, b.phi1, b.mu, b.H);
    ref::BarbuleReference model(s.cases[p.caseIndex].model);
    for (bool reversed : {false, true}) {
      const Vec3& wi = reversed ? p.wo : p.wi;
      const Vec3& wo = reversed ? p.wi : p.wo;
      if (!(wi.z > 0.0f)) continue;
      OffsetInterval common =
          geometry.commonOffsets(geometry.litArc(inPlane(wi).dir), geometry.litArc(inPlane(wo).dir));
      stats.add(std::abs(common.length() - model.commonWidth(toReference(wi), toReference(wo))), describe(s, p));
    }
  }
  std::printf("offsets lit from both directions vs reference: max error of their width %.2e (%s)\n", stats.max,
              stats.worst.c_str());
  EXPECT_LT(stats.max, kCommonEndError) << stats.worst;
}

namespace {

// The R lobe of every pair against the reference: largest error over allowance (kPhaseRounding,
// kReflectionAmplitude); `productionScale` scales production's values.
struct ReflectionErrors {
  ErrorStats ratio;
  double ofEnvelope = 0.0;
  int active = 0, skipped = 0, spurious = 0;
};
ReflectionErrors reflectionErrors(double productionScale = 1.0) {
  const Samples& s = samples();
  std::vector<BarbuleBSDF> bsdfs;
  for (const Case& c : s.cases) bsdfs.emplace_back(c.params);
  ReflectionErrors e;
  for (const Pair& p : s.pairs) {
    if (nearAJump(p.reflection)) {
      ++e.skipped;
      continue;
    }
    Spectrum f = bsdfs[p.caseIndex].evalLobes(BSDFContext{}, p.wi, p.wo, p.wl).reflection;
    if (!(p.reflection.envelope[0] > 0.0)) {
      // Outside the lobe production must be exactly 0 too.
      e.spurious += !f.isZero();
      continue;
    }
    ++e.active;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      double error = std::abs(productionScale * f[k] - p.reflection.value[k]);
      e.ofEnvelope = std::max(e.ofEnvelope, error / p.reflection.envelope[k]);
      e.ratio.add(error / reflectionAllowance(p.reflection, k), describe(s, p));
    }
  }
  return e;
}

}  // namespace

TEST(BarbuleReference, ReflectionLobeMatchesSlow) {
  ReflectionErrors e = reflectionErrors();
  std::printf(
      "R lobe vs reference (%d pairs in the lobe, %d skipped at a jump): max error over allowance %.2f (%s), "
      "max error %.2e of the envelope\n",
      e.active, e.skipped, e.ratio.max, e.ratio.worst.c_str(), e.ofEnvelope);
  EXPECT_GT(e.active, 200);
  EXPECT_LT(e.skipped, int(samples().pairs.size()) / 50);
  EXPECT_EQ(e.spurious, 0);
  EXPECT_LT(e.ratio.max, 1.0) << e.ratio.worst;
}

TEST(BarbuleReference, ReflectionBoundDetectsAOnePercentErrorSlow) {
  double detected = reflectionErrors(1.01).ratio.max;
  std::printf("R lobe with a 1 %% error: max error over allowance %.2f\n", detected);
  EXPECT_GT(detected, 10.0);
}

TEST(BarbuleReference, TRTWithAFineQuadratureMatchesSlow) {
  TRTErrors e = trtErrors(kFineQuadrature);
  std::printf(
      "TRT (256 x 16 nodes) vs reference: max error over allowance %.2f (%s); max relative error %.2e, "
      "%.2e beyond the ends' error; L1 %.2e\n",
      e.ratio.max, e.ratio.worst.c_str(), e.pointwise.max, e.beyondEnds.max, e.l1);
  EXPECT_LT(e.ratio.max, 1.0) << e.ratio.worst;
  // A TRT lobe 1 % off would exceed the allowance (here, not in a test of its own: the reference
  // TRT values are costly to compute).
  double detected = trtErrors(kFineQuadrature, 1.01).ratio.max;
  std::printf("TRT with a 1 %% error: max error over allowance %.2f\n", detected);
  EXPECT_GT(detected, 10.0);
}

TEST(BarbuleReference, TRTWithTheDefaultQuadratureIsWithinItsStatedErrorSlow) {
  TRTErrors e = trtErrors(BarbuleQuadrature{});
  std::printf("TRT (default 4 x 1 nodes) vs reference: max relative error %.2e (%s), L1 %.2e\n", e.pointwise.max,
              e.pointwise.worst.c_str(), e.l1);
  EXPECT_LT(e.pointwise.max, kDefaultTRTBound) << e.pointwise.worst;
  EXPECT_LT(e.l1, kDefaultTRTL1Bound);
}

namespace {

// eval's error over its allowance: the R and TRT lobes' allowances, times the cosine.
double evalRatio(float value, const ref::BarbuleReference::Reflection& R, const ref::BarbuleReference::TRT& T,
                 double melanin, double cosine, int k) {
  double expected = (R.value[k] + T.value[k]) * cosine;
  double allowance = (reflectionAllowance(R, k) + trtAllowance(T, melanin, k)) * cosine;
  return std::abs(value - expected) / allowance;
}

}  // namespace

TEST(BarbuleReference, EvalMatchesInBothRolesSlow) {
  // eval = f(omega_i, omega_o) |cos| with omega_i = wi (barbulebsdf) or omega_i = wo, the light
  // (barbulebsdfev, with the camera's cosine |wi . n|).
  const Samples& s = samples();
  ErrorStats stats;
  for (BarbuleBSDF::Role role : {BarbuleBSDF::Role::CameraIncident, BarbuleBSDF::Role::LightIncident}) {
    std::vector<BarbuleBSDF> bsdfs;
    for (const Case& c : s.cases) bsdfs.emplace_back(c.params, role, kFineQuadrature);
    bool camera = role == BarbuleBSDF::Role::CameraIncident;
    for (size_t i = 0; i < s.pairs.size(); ++i) {
      const Pair& p = s.pairs[i];
      if (!p.hasTRT) continue;
      const ref::BarbuleReference::Reflection& R = camera ? p.reflection : p.reflectionReversed;
      const ref::BarbuleReference::TRT& T = camera ? trtReferences()[i].forward : trtReferences()[i].reversed;
      if (nearAJump(R)) continue;
      double cosine = std::abs(camera ? p.wo.z : p.wi.z);
      Spectrum f = bsdfs[p.caseIndex].eval(BSDFContext{}, p.wi, p.wo, p.wl);
      for (int k = 0; k < kSpectrumSamples; ++k)
        stats.add(evalRatio(f[k], R, T, p.melanin[k], cosine, k), describe(s, p) + (camera ? " camera" : " light"));
    }
  }
  std::printf("eval vs reference, both roles: max error over allowance %.2f (%s)\n", stats.max, stats.worst.c_str());
  EXPECT_LT(stats.max, 1.0) << stats.worst;
}

TEST(BarbuleReference, PerPointOverridesMatchTheReferenceOfThoseParametersSlow) {
  // A feather's per-hit H, mu and film thickness act as the parameters would.
  PCG32 rng(23);
  BarbuleParameters base;
  BarbuleBSDF bsdf(base, BarbuleBSDF::Role::CameraIncident, kFineQuadrature);
  double worst = 0.0;
  for (int i = 0; i < 60; ++i) {
    BarbuleParameters p = base;
    p.mu = uniform(rng, -0.8f, 0.4f);
    p.H = uniform(rng, 1.0f, 2.5f);
    p.height = uniform(rng, 0.4f, 0.7f);
    SurfaceAttributes point;
    point.set(kBarbuleTiltAttribute, p.mu);
    point.set(kBarbuleSpacingAttribute, p.H);
    point.set(kCortexThicknessAttribute, p.height);
    const BSDFContext ctx{TexturePoint(Vec2(), &point), Vec3(), Vec3()};
    Case c = makeCase(p, -1.0f, "override");
    ref::BarbuleReference model(c.model);
    Vec3 wi = upperHemisphere(rng), wo = i % 2 ? uniformSphere(rng) : mirroredAboutALitNormal(rng, model, p.mu, wi);
    Wavelengths wl = randomWavelengths(rng);
    std::vector<double> melanin = melaninAt(c, wl);
    ref::BarbuleReference::Reflection R = model.reflection(toReference(wi), toReference(wo), lambdasOf(wl));
    if (nearAJump(R)) continue;
    ref::BarbuleReference::TRT T = model.trt(toReference(wi), toReference(wo), lambdasOf(wl), melanin);
    Spectrum f = bsdf.eval(ctx, wi, wo, wl);
    for (int k = 0; k < kSpectrumSamples; ++k)
      worst = std::max(worst, evalRatio(f[k], R, T, melanin[k], std::abs(wo.z), k));
    double period = model.spacing() * std::abs(wi.z) / std::hypot(double(wi.x), double(wi.z));
    EXPECT_NEAR(bsdf.coverage(ctx, wi), model.coverage(toReference(wi)), kLitWidthBound / period);
  }
  std::printf("eval with per-point overrides vs reference: max error over allowance %.2f\n", worst);
  EXPECT_LT(worst, 1.0);
}
