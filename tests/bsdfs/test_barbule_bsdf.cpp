// Statistical and structural tests of the barbule BSDF: sample vs pdf (chi-square), the weight
// (a lobe's value over its density) and its mean over regions, the white furnace against an independent average over
// visible normals, the pass-through, reciprocity, the evaluation twin, light from below, per-point overrides and the
// factories.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>
#include "barbule/barbule_film.h"
#include "barbule/cross_section.h"
#include "barbule/normals.h"
#include "bsdfs/barbulebsdf.h"
#include "core/frame.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "optics/film_layer_text.h"
#include "optics/melanin.h"
#include "optics/thin_film.h"
#include "support/barbule_albedo.h"
#include "support/bsdf_test_support.h"
#include "support/chi_square.h"

using namespace columba;
using namespace columba::testing;

namespace {

struct ParameterSet {
  const char* name;
  BarbuleParameters params;
};

BarbuleParameters reference(float height) {
  BarbuleParameters p;  // b 0.25, phi (-0.37, 2.64), mu -0.35, H 1.25: the reference scenes
  p.height = height;
  return p;
}

BarbuleParameters custom(float b, float phi0, float phi1, float mu, float H, float height, RefractiveIndex film) {
  BarbuleParameters p;
  p.b = b;
  p.phi0 = phi0;
  p.phi1 = phi1;
  p.mu = mu;
  p.H = H;
  p.height = height;
  p.filmIOR = film;
  return p;
}

// The cortex over an absorbing layer and an air gap (test values, not a species): the layered film.
// The layered film evaluates its stack by transfer matrices, far slower than the Airy film: the
// slow sweeps take it at one oblique incident direction, the middle one of theirs.
std::vector<Vec3> fewerForLayered(const ParameterSet& set, const std::vector<Vec3>& directions) {
  if (set.params.layersBelow.empty()) return directions;
  return {directions[directions.size() / 2]};
}

BarbuleParameters layered() {
  BarbuleParameters p = reference(0.4f);
  p.layersBelow = parseFilmLayers("1.7+0.1i:0.12, air:0.1");
  return p;
}

// The reference barbule with a squarer, superellipse cross-section.
BarbuleParameters squarer(float exponent) {
  BarbuleParameters p = reference(0.58f);
  p.profileExponent = exponent;
  return p;
}

BarbuleParameters withoutMelanin() {
  BarbuleParameters p = reference(0.59f);
  p.melanin = SpectralDistribution::constant(0.0f);
  return p;
}

// The reference scenes (simulation1/2 and simulation3), a rounder, sparser and oppositely tilted
// barbule, a thin, dense one with a constant-index film and an arc reaching far underneath, and one
// without melanin, whose TRT lobe is zero (the sampler keeps it at its floor share).
const std::vector<ParameterSet>& parameterSets() {
  static const std::vector<ParameterSet> sets = {
      {"reference h0.58", reference(0.58f)},
      {"reference h0.59", reference(0.59f)},
      {"round sparse", custom(0.45f, -1.0f, 1.4f, 0.25f, 2.2f, 0.65f, RefractiveIndex::keratin())},
      {"thin dense n1.56", custom(0.18f, -0.2f, 2.9f, -0.6f, 1.5f, 0.45f, RefractiveIndex::constant(1.56f))},
      {"no melanin", withoutMelanin()},
      {"layered", layered()},
  };
  return sets;
}

Vec3 direction(float thetaDegrees, float phiDegrees) {
  float theta = degToRad(thetaDegrees), phi = degToRad(phiDegrees);
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// theta_i in {0, 30, 60, 80} degrees, several azimuths (one at normal incidence).
std::vector<Vec3> incidentDirections() {
  std::vector<Vec3> dirs = {direction(0.0f, 0.0f)};
  for (float theta : {30.0f, 60.0f, 80.0f})
    for (float phi : {20.0f, 110.0f, 250.0f}) dirs.push_back(direction(theta, phi));
  return dirs;
}

const Wavelengths kWavelengths = Wavelengths::fixed({430.0f, 520.0f, 610.0f, 700.0f});

// Chi-square bins with the barbule axis t as the pole: rows equal in t . w (the R lobe is narrow
// in the angle to t), columns in the azimuth around it.
Vec3 axisAsPole(const Vec3& w) { return {w.z, w.x, w.y}; }
Vec3 fromAxisAsPole(const Vec3& v) { return {v.y, v.z, v.x}; }

double sidak(double familyAlpha, int tests) { return 1.0 - std::pow(1.0 - familyAlpha, 1.0 / tests); }

// The chi-square test of the scattering samples from wi (pass-through left out) against pdf(), on
// bins x bins cells around the barbule axis, each integrated with quadrature x quadrature points;
// `scattered` counts the samples that scattered.
ChiSquareResult scatteringChiSquare(const BarbuleBSDF& bsdf, const Vec3& wi, int samples, int bins, int quadrature,
                                    int* scattered = nullptr) {
  const BSDFContext ctx;
  return chiSquareDirectionTest(
      [&](PCG32& rng) -> std::optional<Vec3> {
        float uComponent = rng.nextFloat();
        Vec2 u(rng.nextFloat(), rng.nextFloat());
        auto s = bsdf.sample(ctx, wi, kWavelengths, uComponent, u);
        if (!s || s->passThrough) return std::nullopt;
        if (scattered) ++*scattered;
        return axisAsPole(s->wo);
      },
      [&](const Vec3& w) { return double(bsdf.pdf(ctx, wi, fromAxisAsPole(w), kWavelengths)); }, samples, bins, bins,
      quadrature);
}

}  // namespace

namespace {

// Which lobe's value over that lobe's density a `barbulebsdf` sample weighs, within 1e-3 at every
// wavelength: R, TRT, or neither (nullopt). R's density is the one the sample reports less TRT's,
// since an R sample carries the share of visible angles it was drawn with.
std::optional<bool> reflectedWeight(const BarbuleBSDF& bsdf, const BSDFContext& ctx, const Vec3& wi,
                                    const BSDFSample& s) {
  BarbuleBSDF::Lobes lobes = bsdf.evalLobes(ctx, wi, s.wo, kWavelengths);
  BarbuleBSDF::LobeDensities density = bsdf.lobePdfs(ctx, wi, s.wo, kWavelengths);
  auto matches = [&](const Spectrum& value, float lobeDensity) {
    if (!(lobeDensity > 0.0f)) return false;
    for (int k = 0; k < kSpectrumSamples; ++k) {
      float expected = value[k] * std::abs(s.wo.z) / lobeDensity;
      if (!(std::abs(s.weight[k] - expected) <= 1e-3f * expected + 1e-7f)) return false;
    }
    return true;
  };
  if (matches(lobes.reflection, s.pdf - density.trt)) return true;
  if (matches(lobes.trt, density.trt)) return false;
  return std::nullopt;
}

}  // namespace

TEST(BarbuleBSDF, SampledDirectionsFollowThePdfSlow) {
  const std::vector<Vec3> incident = incidentDirections();
  int tests = 0;
  for (const ParameterSet& set : parameterSets()) tests += int(fewerForLayered(set, incident).size());
  const double threshold = sidak(0.01, tests);
  const BSDFContext ctx;
  std::printf("chi-square of sample() against pdf(), %d tests, per-test threshold %.2e (family alpha 0.01)\n", tests,
              threshold);
  for (const ParameterSet& set : parameterSets()) {
    BarbuleBSDF bsdf(set.params);
    double minP = 1.0;
    for (const Vec3& wi : fewerForLayered(set, incident)) {
      int scattered = 0;
      ChiSquareResult result = scatteringChiSquare(bsdf, wi, 150000, 48, 10, &scattered);
      std::printf("  %-18s wi (%6.3f %6.3f %6.3f): %6d scattered, p = %.3g\n", set.name, wi.x, wi.y, wi.z, scattered,
                  result.pValue);
      EXPECT_GT(result.pValue, threshold)
          << set.name << " wi " << wi.x << " " << wi.y << " " << wi.z << ": " << result.message;
      minP = std::min(minP, result.pValue);
    }
    std::printf("  %-18s min p = %.3g\n", set.name, minP);
  }
}

// With BSDFContext::passThroughByCaller (the direct integrator carries T itself) every sample
// scatters, pdf() is the scattering density given that (the usual one times the same factor for
// every omega_o of one omega_i), sampled directions follow it, and the weight is the drawing
// lobe's value over that lobe's share of it.
TEST(BarbuleBSDF, ACallerCarryingPassThroughGetsScatteringSamplesFollowingTheirPdf) {
  const BSDFContext usual;
  BSDFContext byCaller;
  byCaller.passThroughByCaller = true;
  const std::vector<Vec3> incident = incidentDirections();
  const int chiSquareSets = 2;
  const double threshold = sidak(0.01, chiSquareSets * int(incident.size()));
  int set = 0;
  for (const ParameterSet& parameters : parameterSets()) {
    BarbuleBSDF bsdf(parameters.params);
    for (const Vec3& wi : incident) {
      PCG32 rng(5);
      float ratio = -1.0f;
      int scattered = 0;
      for (int i = 0; i < 2000; ++i) {
        auto s = bsdf.sample(byCaller, wi, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!s) continue;
        ASSERT_FALSE(s->passThrough) << parameters.name;
        ++scattered;
        float pdf = bsdf.pdf(byCaller, wi, s->wo, kWavelengths), pdfUsual = bsdf.pdf(usual, wi, s->wo, kWavelengths);
        EXPECT_NEAR(s->pdf, pdf, 0.02f * pdf) << parameters.name;
        ASSERT_TRUE(reflectedWeight(bsdf, byCaller, wi, *s).has_value()) << parameters.name;
        ASSERT_GE(pdf, pdfUsual) << parameters.name;
        if (ratio < 0.0f) ratio = pdf / pdfUsual;
        EXPECT_NEAR(pdf / pdfUsual, ratio, 1e-4f * ratio) << parameters.name;
      }
      EXPECT_GT(scattered, 500) << parameters.name << " wi " << wi.x << " " << wi.y << " " << wi.z;
      if (set >= chiSquareSets) continue;
      ChiSquareResult result = chiSquareDirectionTest(
          [&](PCG32& r) -> std::optional<Vec3> {
            float uComponent = r.nextFloat();
            Vec2 u(r.nextFloat(), r.nextFloat());
            auto s = bsdf.sample(byCaller, wi, kWavelengths, uComponent, u);
            if (!s) return std::nullopt;
            return axisAsPole(s->wo);
          },
          [&](const Vec3& w) { return double(bsdf.pdf(byCaller, wi, fromAxisAsPole(w), kWavelengths)); }, 600000, 48,
          48, 10);
      EXPECT_GT(result.pValue, threshold)
          << parameters.name << " wi " << wi.x << " " << wi.y << " " << wi.z << ": " << result.message;
    }
    ++set;
  }
}

TEST(BarbuleBSDF, SampleWeightIsItsLobesValueOverItsDensity) {
  // `barbulebsdf` weighs a sample by the value of the lobe that drew it over that lobe's density,
  // the evaluation twin by eval over the density the sample reports. pdf() gives that density
  // within 1e-4, except for R samples drawn where the share of visible longitudinal angles changes fast
  // with the normal: recomputed at the half vector's normal, equal to the sampled one up to
  // rounding, the share can differ. Here 70 of 232,728 samples differ by more than 1e-4, at most
  // by 0.9 %; in renders a jump by orders of magnitude was seen 3 times in 2.7e8 samples (a cut
  // where a(theta) peaks), which is why a sample reports the density it was drawn with.
  const BSDFContext ctx;
  int checked = 0, otherShare = 0, reflected = 0, trt = 0;
  for (const ParameterSet& set : parameterSets())
    for (BarbuleBSDF::Role role : {BarbuleBSDF::Role::CameraIncident, BarbuleBSDF::Role::LightIncident}) {
      BarbuleBSDF bsdf(set.params, role);
      PCG32 rng(11);
      int checkedHere = 0;
      for (const Vec3& wi : incidentDirections())
        for (int i = 0; i < 3000; ++i) {
          auto s = bsdf.sample(ctx, wi, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
          if (!s || s->passThrough) continue;
          ASSERT_FALSE(s->delta);
          ASSERT_GT(s->pdf, 0.0f);
          float pdf = bsdf.pdf(ctx, wi, s->wo, kWavelengths);
          Spectrum f = bsdf.eval(ctx, wi, s->wo, kWavelengths);
          if (std::abs(s->pdf - pdf) > 1e-4f * pdf) ++otherShare;
          EXPECT_NEAR(s->pdf, pdf, 0.02f * pdf) << set.name;
          ++checkedHere;
          if (role == BarbuleBSDF::Role::CameraIncident) {
            std::optional<bool> lobe = reflectedWeight(bsdf, ctx, wi, *s);
            ASSERT_TRUE(lobe.has_value()) << set.name;
            ++(*lobe ? reflected : trt);
            continue;
          }
          for (int k = 0; k < kSpectrumSamples; ++k)
            ASSERT_NEAR(s->weight[k], f[k] / s->pdf, 1e-4f * (f[k] / s->pdf) + 1e-7f) << set.name << " lambda " << k;
        }
      EXPECT_GT(checkedHere, 1000) << set.name;
      checked += checkedHere;
    }
  std::printf("%d of %d samples report another density than pdf(); R %d and TRT %d weights\n", otherShare, checked,
              reflected, trt);
  EXPECT_LE(otherShare, checked / 2000);
  EXPECT_GT(reflected, 10000);
  EXPECT_GT(trt, 10000);
}

// A caller that reads no pdf (BSDFVertexRequest::samplePdf false, the direct integrator without
// emitter samples) gets an R sample's weight in closed form, F G_o v W cos(theta_i) / (H |cos_i|
// s_R), in which the NDF, the visible-normal density and the half vector cancel; a TRT sample skips
// R's density. The weight must be the one the full computation gives for the same sample. They
// differ only where the sampled normal lies on the edge of what reflects (theta at +-thetaD, the
// offset at the end of the lit arc): recomputed from the half vector, rounding can put it outside,
// and the full computation then drops the sample.
TEST(BarbuleBSDF, AWeightWithoutPdfIsTheWeightWithIt) {
  int compared = 0, differing = 0;
  for (bool byCaller : {false, true}) {
    BSDFContext ctx;
    ctx.passThroughByCaller = byCaller;
    for (const ParameterSet& set : parameterSets()) {
      BarbuleBSDF bsdf(set.params, BarbuleBSDF::Role::CameraIncident);
      PCG32 rng(5);
      for (const Vec3& wi : incidentDirections())
        for (int i = 0; i < 2000; ++i) {
          BSDFVertexRequest request;
          request.sample = true;
          request.uComponent = rng.nextFloat();
          request.u = Vec2(rng.nextFloat(), rng.nextFloat());
          std::optional<BSDFSample> full = bsdf.queryVertex(ctx, wi, kWavelengths, request).sampled;
          request.samplePdf = false;
          std::optional<BSDFSample> quick = bsdf.queryVertex(ctx, wi, kWavelengths, request).sampled;
          if (!full && !quick) continue;
          ++compared;
          if (!full || !quick) {
            ++differing;
            continue;
          }
          ASSERT_EQ(full->wo, quick->wo) << set.name;
          ASSERT_EQ(full->passThrough, quick->passThrough);
          if (!quick->passThrough) {
            EXPECT_EQ(quick->pdf, 0.0f);
          }
          bool same = true;
          for (int k = 0; k < kSpectrumSamples; ++k)
            same = same && std::abs(full->weight[k] - quick->weight[k]) <= 1e-4f * std::abs(full->weight[k]) + 1e-7f;
          differing += !same;
        }
    }
  }
  std::printf("%d of %d samples weigh differently without the pdf\n", differing, compared);
  EXPECT_GT(compared, 100000);
  EXPECT_LE(differing, compared / 2000);
}

namespace {

// The integrals of eval over omega_o, whole or by region, of the BSDF's own lobes.
template <typename RegionOf>
std::vector<LobeAlbedo> integrateLobesByRegion(const BarbuleBSDF& bsdf, const Vec3& wi, int regions,
                                               const RegionOf& regionOf) {
  const BSDFContext ctx;
  return integrateLobeGrid([&](const Vec3& wo) { return bsdf.evalLobes(ctx, wi, wo, kWavelengths); }, wi, regions,
                           regionOf);
}
LobeAlbedo integrateLobes(const BarbuleBSDF& bsdf, const Vec3& wi) {
  return integrateLobesByRegion(bsdf, wi, 1, [](const Vec3&) { return 0; }).front();
}

// The mean of 100,000 sample weights from wi (T included) with its standard error, per wavelength.
struct WeightMean {
  Spectrum mean, sigma;
};
WeightMean meanSampleWeight(const BarbuleBSDF& bsdf, const Vec3& wi) {
  const BSDFContext ctx;
  PCG32 rng(5, 9);
  const int n = 100000;
  Spectrum mean(0.0f), meanSqr(0.0f);
  for (int i = 0; i < n; ++i) {
    auto s = bsdf.sample(ctx, wi, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s) continue;
    mean += s->weight / float(n);
    meanSqr += s->weight * s->weight / float(n);
  }
  WeightMean out{mean, Spectrum(0.0f)};
  for (int k = 0; k < kSpectrumSamples; ++k)
    out.sigma[k] = std::sqrt(std::max(meanSqr[k] - mean[k] * mean[k], 0.0f) / n);
  return out;
}

}  // namespace

// The two quadratures (of eval over directions, and of the lobes' means over visible normals)
// differ from each other by their discretisation: measured over the 80 cases of the single-film
// sets (with the layered film's 20 at all five directions: R -0.00002 over 120, TRT 0.0022 over
// 100), the ratio
// integral / means - 1 is 0.00006 on average (spread 0.0006, at most 0.0044) for R and 0.0021
// (spread 0.0055, -0.0086 to +0.0207) for TRT. Each case must lie within bounds that hold all of
// these (with a small absolute floor); the mean over all cases, where the discretisation errors
// of different cases cancel, must lie within a narrow band around its measured value, so that a
// loss of 1 % of R's or TRT's energy (which moves every case) fails.
constexpr double kMeanRatioR = 0.00006, kMeanRatioTRT = 0.0021, kMeanRatioBand = 0.004;

TEST(BarbuleBSDF, WhiteFurnaceMatchesTheVisibleNormalMeansSlow) {
  const BSDFContext ctx;
  std::printf("furnace: integral of eval + t against r (I_R + I_TRT) + t, per wavelength (430/520/610/700 nm)\n");
  double sumRatioR = 0, sumRatioTRT = 0;
  int ratiosR = 0, ratiosTRT = 0;
  for (const ParameterSet& set : parameterSets()) {
    BarbuleBSDF bsdf(set.params);
    for (const Vec3& wi :
         fewerForLayered(set, {direction(0.0f, 0.0f), direction(30.0f, 20.0f), direction(60.0f, 110.0f),
                               direction(80.0f, 250.0f), direction(45.0f, 0.0f)})) {
      float t = bsdf.passThrough(ctx, wi, kWavelengths)[0];
      EXPECT_NEAR(t, 1.0f - bsdf.coverage(ctx, wi), 1e-6f);
      LobeAlbedo integral = integrateLobes(bsdf, wi), expected = visibleNormalMeans(set.params, wi, kWavelengths);

      // The expected value of the sample weight (T included) is the same total, by Monte Carlo.
      const WeightMean weights = meanSampleWeight(bsdf, wi);
      const Spectrum& mean = weights.mean;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        float total = integral.reflection[k] + integral.trt[k] + t;
        float predicted = expected.reflection[k] + expected.trt[k] + t;
        float sigma = weights.sigma[k];
        std::printf(
            "  %-18s wi (%6.3f %6.3f %6.3f) %3.0f nm: R %.5f (means %.5f) TRT %.5f (means %.5f) t %.4f total "
            "%.5f, MC %.5f +- %.5f\n",
            set.name, wi.x, wi.y, wi.z, kWavelengths[k], integral.reflection[k], expected.reflection[k],
            integral.trt[k], expected.trt[k], t, total, mean[k], sigma);
        EXPECT_NEAR(integral.reflection[k], expected.reflection[k], 3e-3f * expected.reflection[k] + 2e-5f);
        EXPECT_NEAR(integral.trt[k], expected.trt[k], 2e-2f * expected.trt[k] + 2e-5f);
        if (expected.reflection[k] > 1e-3f) {
          sumRatioR += integral.reflection[k] / expected.reflection[k] - 1.0;
          ++ratiosR;
        }
        if (expected.trt[k] > 1e-3f) {
          sumRatioTRT += integral.trt[k] / expected.trt[k] - 1.0;
          ++ratiosTRT;
        }
        EXPECT_NEAR(mean[k], total, 4.0f * sigma + 5e-3f * (total - t));
        EXPECT_LE(total, 1.0f + 1e-4f);
        EXPECT_LE(predicted, 1.0f + 1e-4f);
      }
    }
  }
  ASSERT_GT(ratiosR, 40);
  ASSERT_GT(ratiosTRT, 40);
  std::printf("mean ratio integral / means - 1: R %.5f over %d cases, TRT %.5f over %d\n", sumRatioR / ratiosR, ratiosR,
              sumRatioTRT / ratiosTRT, ratiosTRT);
  EXPECT_NEAR(sumRatioR / ratiosR, kMeanRatioR, kMeanRatioBand);
  EXPECT_NEAR(sumRatioTRT / ratiosTRT, kMeanRatioTRT, kMeanRatioBand);
}

// Superellipse cross-sections. Where a flat side's normal points along an axis the radius of
// curvature, and with it the normal distribution and the pdf, grows without bound (like
// |phi - axis|^(-(p-2)/(p-1))): an integrable singularity along a curve of directions. The
// midpoint quadratures of the tests above misjudge such a curve's mass by a few per cent (at
// normal incidence, p 3, the curve runs along one column of 48 x 48 chi-square bins, whose
// expected counts then alternate 5167, 4113, 4383 against a flat 4,700 observed). So here: the
// chi-square test at p 3 and 4 and oblique directions, whose curves cross the bins, with 32 x 32
// quadrature points per bin (at p 8 the singularity, near |phi|^(-6/7), defeats any bin
// quadrature: p-values collapse to 0 where the furnace below agrees); and the white furnace by
// the sample weights' mean (T included) against the independent means over visible normals,
// which need no pdf, at p 3, 8 and 16 (rounded rectangles), normal incidence included.
TEST(BarbuleBSDF, SuperellipseSamplesFollowThePdfAndWeighTheirEnergySlow) {
  const BSDFContext ctx;
  const std::vector<Vec3> oblique = {direction(30.0f, 20.0f), direction(60.0f, 110.0f), direction(80.0f, 250.0f)};
  const double threshold = sidak(0.01, 6);
  for (float exponent : {3.0f, 4.0f}) {
    BarbuleBSDF bsdf(squarer(exponent));
    for (const Vec3& wi : oblique) {
      ChiSquareResult result = scatteringChiSquare(bsdf, wi, 60000, 20, 32);
      std::printf("superellipse p %g wi (%6.3f %6.3f %6.3f): chi-square p = %.3g\n", exponent, wi.x, wi.y, wi.z,
                  result.pValue);
      EXPECT_GT(result.pValue, threshold) << "p " << exponent << ": " << result.message;
    }
  }
  for (float exponent : {3.0f, 8.0f, 16.0f}) {
    // A fine TRT quadrature: with the default 4 offsets TRT on flat sides is off by up to 3 %, which is
    // the quadrature (docs/model.md), not the sampling this tests.
    BarbuleBSDF bsdf(squarer(exponent), BarbuleBSDF::Role::CameraIncident, BarbuleQuadrature{16, 4, 4});
    for (const Vec3& wi : {direction(0.0f, 0.0f), direction(60.0f, 110.0f)}) {
      float t = bsdf.passThrough(ctx, wi, kWavelengths)[0];
      LobeAlbedo expected = visibleNormalMeans(squarer(exponent), wi, kWavelengths);
      const WeightMean weights = meanSampleWeight(bsdf, wi);
      const Spectrum& mean = weights.mean;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        float total = expected.reflection[k] + expected.trt[k] + t;
        float sigma = weights.sigma[k];
        std::printf(
            "  p %g wi (%6.3f %6.3f %6.3f) %3.0f nm: means R %.5f TRT %.5f t %.4f total %.5f, MC %.5f +- %.5f\n",
            exponent, wi.x, wi.y, wi.z, kWavelengths[k], expected.reflection[k], expected.trt[k], t, total, mean[k],
            sigma);
        EXPECT_NEAR(mean[k], total, 4.0f * sigma + 2e-3f * (total - t));
        EXPECT_LE(total, 1.0f + 1e-4f);
      }
    }
  }
}

// Each lobe estimated by its own samples is unbiased against any function of omega_o, not only in
// total (the white furnace): the mean of weight x [omega_o in A] is the integral of eval over A,
// for the four quadrants A of (above or below the vane) x (x positive or negative).
TEST(BarbuleBSDF, SampleWeightsIntegrateEvalOverEachRegion) {
  const BSDFContext ctx;
  auto quadrant = [](const Vec3& w) { return (w.z > 0.0f ? 2 : 0) + (w.x > 0.0f ? 1 : 0); };
  int compared = 0;
  for (const ParameterSet& set : {parameterSets()[0], parameterSets()[2]}) {
    BarbuleBSDF bsdf(set.params);
    for (const Vec3& wi : {direction(20.0f, 30.0f), direction(60.0f, 110.0f), direction(75.0f, 250.0f)}) {
      std::vector<LobeAlbedo> integral = integrateLobesByRegion(bsdf, wi, 4, quadrant);
      PCG32 rng(21, 3);
      const int n = 200000;
      std::array<Spectrum, 4> mean{}, meanSqr{};
      for (int i = 0; i < n; ++i) {
        auto s = bsdf.sample(ctx, wi, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!s || s->passThrough) continue;
        int a = quadrant(s->wo);
        mean[size_t(a)] += s->weight / float(n);
        meanSqr[size_t(a)] += s->weight * s->weight / float(n);
      }
      for (int a = 0; a < 4; ++a)
        for (int k = 0; k < kSpectrumSamples; ++k) {
          float expected = integral[size_t(a)].reflection[k] + integral[size_t(a)].trt[k];
          float m = mean[size_t(a)][k];
          float sigma = std::sqrt(std::max(meanSqr[size_t(a)][k] - m * m, 0.0f) / n);
          EXPECT_NEAR(m, expected, 4.0f * sigma + 5e-3f * expected + 1e-5f)
              << set.name << " wi " << wi.x << " " << wi.y << " " << wi.z << " quadrant " << a << " lambda " << k;
          compared += expected > 1e-3f;
        }
    }
  }
  EXPECT_GT(compared, 40);
}

TEST(BarbuleBSDF, PassThroughMatchesTheTransmittedFractionSlow) {
  const BSDFContext ctx;
  for (const ParameterSet& set : parameterSets()) {
    BarbuleBSDF bsdf(set.params);
    for (const Vec3& wi : incidentDirections()) {
      float t = bsdf.passThrough(ctx, wi, kWavelengths)[0];
      PCG32 rng(13);
      const int n = 20000;
      int chosen = 0;
      float probability = -1.0f;
      for (int i = 0; i < n; ++i) {
        auto s = bsdf.sample(ctx, wi, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
        if (!s || !s->passThrough) continue;
        ++chosen;
        ASSERT_TRUE(s->delta);
        EXPECT_EQ(s->wo, -wi);
        // weight = t / P(T) at every wavelength, with P(T) the reported probability.
        for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_NEAR(s->weight[k] * s->pdf, t, 1e-5f);
        probability = s->pdf;
      }
      if (chosen == 0) {
        // P(T) >= t / 2 (the other lobes' weights are at most r each), so only a negligible t can
        // go unchosen in this many draws.
        EXPECT_LT(t, 1e-3f);
        continue;
      }
      // P(T) is the frequency of choosing it (binomial, 5 sigma).
      double sigma = std::sqrt(probability * (1.0 - probability) / n);
      EXPECT_NEAR(double(chosen) / n, probability, 5.0 * sigma + 1e-9) << set.name;
    }
  }
}

TEST(BarbuleBSDF, ReflectionLobeIsReciprocalAndTRTIsNot) {
  const BSDFContext ctx;
  BarbuleBSDF bsdf(reference(0.58f));
  PCG32 rng(21);
  int reflecting = 0;
  double largestTRTAsymmetry = 0.0;
  for (int i = 0; i < 200000; ++i) {
    Vec3 a = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    // Mirror-like pairs, so that many of them meet the narrow lobe.
    Vec3 b = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    b.y = -a.y + (rng.nextFloat() - 0.5f) * 0.2f;
    if (b.y * b.y >= 1.0f) continue;
    b = normalize(Vec3(b.x, b.y, std::abs(b.z) + 1e-3f));
    BarbuleBSDF::Lobes ab = bsdf.evalLobes(ctx, a, b, kWavelengths), ba = bsdf.evalLobes(ctx, b, a, kWavelengths);
    for (int k = 0; k < kSpectrumSamples; ++k) {
      // Equal up to float rounding of omega_i . m against omega_o . m, which the film amplifies near
      // grazing incidence (where f_R is tiny).
      ASSERT_NEAR(ab.reflection[k], ba.reflection[k], 1e-3f * ab.reflection[k] + 1e-5f);
      if (ab.trt[k] > 0.0f || ba.trt[k] > 0.0f)
        largestTRTAsymmetry =
            std::max(largestTRTAsymmetry, double(std::abs(ab.trt[k] - ba.trt[k]) / std::max(ab.trt[k], ba.trt[k])));
    }
    if (ab.reflection[0] > 0.0f) ++reflecting;
  }
  EXPECT_GT(reflecting, 5000);
  // TRT averages over the normals lit from omega_i: swapping the directions changes it.
  EXPECT_GT(largestTRTAsymmetry, 0.1);
}

TEST(BarbuleBSDF, EvaluationTwinSwapsTheDirections) {
  const BSDFContext ctx;
  BarbuleParameters p = reference(0.58f);
  BarbuleBSDF camera(p, BarbuleBSDF::Role::CameraIncident), light(p, BarbuleBSDF::Role::LightIncident);
  PCG32 rng(31);
  for (int i = 0; i < 20000; ++i) {
    Vec3 wi = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    // barbulebsdf: f(wi, wo) |cos wo|. barbulebsdfev is the scatterometer quantity with the light
    // at wo and the camera at wi: f(wo, wi) |cos wi|, i.e. barbulebsdf with the roles swapped.
    BarbuleBSDF::Lobes forward = camera.evalLobes(ctx, wi, wo, kWavelengths);
    BarbuleBSDF::Lobes swapped = camera.evalLobes(ctx, wo, wi, kWavelengths);
    Spectrum expectedCamera = (forward.reflection + forward.trt) * std::abs(wo.z);
    Spectrum expectedLight = (swapped.reflection + swapped.trt) * std::abs(wi.z);
    Spectrum fc = camera.eval(ctx, wi, wo, kWavelengths), fl = light.eval(ctx, wi, wo, kWavelengths);
    Spectrum rolesSwapped = camera.eval(ctx, wo, wi, kWavelengths);
    for (int k = 0; k < kSpectrumSamples; ++k) {
      ASSERT_NEAR(fc[k], expectedCamera[k], 1e-6f * expectedCamera[k] + 1e-9f);
      ASSERT_NEAR(fl[k], expectedLight[k], 1e-6f * expectedLight[k] + 1e-9f);
      ASSERT_NEAR(fl[k], rolesSwapped[k], 1e-6f * rolesSwapped[k] + 1e-9f);
    }
    // Both sample alike and report the same density.
    EXPECT_EQ(camera.pdf(ctx, wi, wo, kWavelengths), light.pdf(ctx, wi, wo, kWavelengths));
  }
}

TEST(BarbuleBSDF, CombinedQueriesMatchTheSeparateOnes) {
  SurfaceAttributes point;
  point.set(kBarbuleSpacingAttribute, 1.6f);
  point.set(kBarbuleTiltAttribute, -0.2f);
  for (const BSDFContext& ctx : {BSDFContext{}, BSDFContext{TexturePoint(Vec2(), &point), Vec3(), Vec3()}})
    for (auto role : {BarbuleBSDF::Role::CameraIncident, BarbuleBSDF::Role::LightIncident}) {
      BarbuleBSDF bsdf(reference(0.58f), role);
      PCG32 rng(37);
      int nonZero = 0, sampled = 0;
      for (int i = 0; i < 5000; ++i) {
        // Both directions on the whole sphere: the evaluation twin reflects toward a camera below too.
        Vec3 wi = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        float uComponent = rng.nextFloat();
        Vec2 u(rng.nextFloat(), rng.nextFloat());
        Spectrum f = bsdf.eval(ctx, wi, wo, kWavelengths);
        float pdf = bsdf.pdf(ctx, wi, wo, kWavelengths);
        nonZero += !f.isZero();
        // queryVertex gives what it is asked for, as the separate calls do: eval (with pdf or not)
        // toward a light direction, sample, the pass-through.
        BSDFVertexRequest request;
        request.woLights = &wo;
        request.woLightCount = i % 3 ? 1 : 0;
        BSDFEvalPdf vertexToLight;
        request.toLights = &vertexToLight;
        request.lightPdf = i % 3 == 1;
        request.sample = true;
        request.uComponent = uComponent;
        request.u = u;
        request.passThrough = i % 2;
        BSDFVertexQueries vertex = bsdf.queryVertex(ctx, wi, kWavelengths, request);
        BSDFEvalPdf toLight = request.woLightCount == 0 ? BSDFEvalPdf{} : BSDFEvalPdf{f, request.lightPdf ? pdf : 0.0f};
        for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_EQ(vertexToLight.value[k], toLight.value[k]);
        ASSERT_EQ(vertexToLight.pdf, toLight.pdf);
        ASSERT_EQ(vertex.passThrough[0], request.passThrough ? bsdf.passThrough(ctx, wi, kWavelengths)[0] : 0.0f);
        std::optional<BSDFSample> alone = bsdf.sample(ctx, wi, kWavelengths, uComponent, u);
        ASSERT_EQ(vertex.sampled.has_value(), alone.has_value());
        if (!alone) continue;
        ++sampled;
        EXPECT_EQ(vertex.sampled->wo.x, alone->wo.x);
        EXPECT_EQ(vertex.sampled->wo.y, alone->wo.y);
        EXPECT_EQ(vertex.sampled->wo.z, alone->wo.z);
        EXPECT_EQ(vertex.sampled->pdf, alone->pdf);
        EXPECT_EQ(vertex.sampled->passThrough, alone->passThrough);
        for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_EQ(vertex.sampled->weight[k], alone->weight[k]);
      }
      EXPECT_GT(nonZero, 500);
      EXPECT_GT(sampled, 2000);
    }
}

namespace {
// Records the targets it is handed and chooses the candidate given at construction.
class RecordingChooser final : public LightChooser {
 public:
  explicit RecordingChooser(int choice) : choice_(choice) {}
  int choose(const BSDFEvalPdf* targets, int count) override {
    seen.assign(targets, targets + count);
    return choice_;
  }
  std::vector<BSDFEvalPdf> seen;

 private:
  int choice_;
};

// A vertex query toward `count` light directions with densities, through `chooser`.
void queryWithChooser(const BarbuleBSDF& bsdf, const BSDFContext& ctx, const Vec3& wi, const Vec3* wo, int count,
                      BSDFEvalPdf* toLights, LightChooser& chooser) {
  BSDFVertexRequest request;
  request.woLights = wo;
  request.woLightCount = count;
  request.toLights = toLights;
  request.lightPdf = true;
  request.chooseLight = &chooser;
  bsdf.queryVertex(ctx, wi, kWavelengths, request);
}
}  // namespace

// With a LightChooser, the barbule hands it R's value plus a bound of TRT toward each candidate
// (no TRT quadrature): positive at every wavelength where the value is, which keeps resampling
// unbiased, and at least R. The chosen candidate's entry then holds the exact value and density.
TEST(BarbuleBSDF, ResamplingTargetsArePositiveWhereverTheValueIsAndTheChosenOneIsExact) {
  SurfaceAttributes point;
  point.set(kBarbuleSpacingAttribute, 1.6f);
  point.set(kBarbuleTiltAttribute, -0.2f);
  for (const BSDFContext& ctx : {BSDFContext{}, BSDFContext{TexturePoint(Vec2(), &point), Vec3(), Vec3()}}) {
    BarbuleBSDF bsdf(reference(0.58f));
    ASSERT_TRUE(bsdf.hasCheapResamplingTargets());
    PCG32 rng(43);
    int positive = 0, trtOnly = 0;
    for (int i = 0; i < 4000; ++i) {
      Vec3 wi = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
      std::array<Vec3, 4> wo;
      for (Vec3& w : wo) w = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
      const int choice = int(rng.nextFloat() * 4.0f) % 4;
      RecordingChooser chooser(choice);
      std::array<BSDFEvalPdf, 4> toLights;
      queryWithChooser(bsdf, ctx, wi, wo.data(), 4, toLights.data(), chooser);
      ASSERT_EQ(chooser.seen.size(), 4u);
      for (int k = 0; k < 4; ++k) {
        BarbuleBSDF::Lobes lobes = bsdf.evalLobes(ctx, wi, wo[size_t(k)], kWavelengths);
        const float cosO = std::abs(wo[size_t(k)].z);
        for (int j = 0; j < kSpectrumSamples; ++j) {
          const float value = (lobes.reflection[j] + lobes.trt[j]) * cosO, target = chooser.seen[size_t(k)].value[j];
          if (value > 0.0f) {
            ASSERT_GT(target, 0.0f) << "wi " << wi.z << " wo " << wo[size_t(k)].z;
          }
          ASSERT_GE(target, lobes.reflection[j] * cosO * (1.0f - 1e-5f));
        }
        positive += lobes.trt[0] > 0.0f;
        trtOnly += lobes.trt[0] > 0.0f && lobes.reflection[0] == 0.0f;
      }
      Spectrum f = bsdf.eval(ctx, wi, wo[size_t(choice)], kWavelengths);
      for (int j = 0; j < kSpectrumSamples; ++j) ASSERT_EQ(toLights[size_t(choice)].value[j], f[j]);
      ASSERT_EQ(toLights[size_t(choice)].pdf, bsdf.pdf(ctx, wi, wo[size_t(choice)], kWavelengths));
    }
    // The check saw TRT where R is zero, where only the bound keeps the target positive.
    EXPECT_GT(positive, 2000);
    EXPECT_GT(trtOnly, 500);
  }
}

// barbulebsdfev (omega_i = wo) has no cheap targets: it hands the chooser its values and densities.
TEST(BarbuleBSDF, TheEvaluationTwinHandsAChooserItsValues) {
  const BSDFContext ctx;
  BarbuleBSDF bsdf(reference(0.58f), BarbuleBSDF::Role::LightIncident);
  EXPECT_FALSE(bsdf.hasCheapResamplingTargets());
  PCG32 rng(47);
  for (int i = 0; i < 1000; ++i) {
    Vec3 wi = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    std::array<Vec3, 3> wo;
    for (Vec3& w : wo) w = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    RecordingChooser chooser(i % 3);
    std::array<BSDFEvalPdf, 3> toLights;
    queryWithChooser(bsdf, ctx, wi, wo.data(), 3, toLights.data(), chooser);
    ASSERT_EQ(chooser.seen.size(), 3u);
    for (size_t k = 0; k < 3; ++k) {
      Spectrum f = bsdf.eval(ctx, wi, wo[k], kWavelengths);
      for (int j = 0; j < kSpectrumSamples; ++j) {
        ASSERT_EQ(chooser.seen[k].value[j], f[j]);
        ASSERT_EQ(toLights[k].value[j], f[j]);
      }
      ASSERT_EQ(toLights[k].pdf, bsdf.pdf(ctx, wi, wo[k], kWavelengths));
    }
  }
}

TEST(BarbuleBSDF, LightFromBelowOnlyPassesWithTheCoverageOfTheSameLine) {
  const BSDFContext ctx;
  for (const ParameterSet& set : parameterSets()) {
    BarbuleBSDF bsdf(set.params);
    PCG32 rng(41);
    for (int i = 0; i < 2000; ++i) {
      // Light along `below` crosses the layer on the same line as light along -below from above.
      Vec3 above = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
      Vec3 below = -above;
      Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
      EXPECT_TRUE(bsdf.eval(ctx, below, wo, kWavelengths).isZero());
      EXPECT_EQ(bsdf.pdf(ctx, below, wo, kWavelengths), 0.0f);
      float t = bsdf.passThrough(ctx, below, kWavelengths)[0];
      EXPECT_EQ(t, bsdf.passThrough(ctx, above, kWavelengths)[0]);
      auto s = bsdf.sample(ctx, below, kWavelengths, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      if (t > 0.0f) {
        ASSERT_TRUE(s.has_value());
        EXPECT_TRUE(s->passThrough);
        EXPECT_NEAR(s->weight[0] * s->pdf, t, 1e-6f);
      } else {
        EXPECT_FALSE(s.has_value());
      }
    }
  }
}

TEST(BarbuleBSDF, PerPointOverridesActLikeTheParameters) {
  BarbuleParameters base = reference(0.58f);
  BarbuleBSDF bsdf(base);
  SurfaceAttributes point;
  point.set(kBarbuleSpacingAttribute, 1.6f);
  point.set(kBarbuleTiltAttribute, -0.2f);
  point.set(kCortexThicknessAttribute, 0.63f);
  const BSDFContext ctx{TexturePoint(Vec2(), &point), Vec3(), Vec3()};
  BarbuleParameters changed = base;
  changed.H = 1.6f;
  changed.mu = -0.2f;
  changed.height = 0.63f;
  BarbuleBSDF expected(changed);
  const BSDFContext none;
  PCG32 rng(51);
  int differing = 0;
  for (int i = 0; i < 5000; ++i) {
    Vec3 wi = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    Spectrum a = bsdf.eval(ctx, wi, wo, kWavelengths), b = expected.eval(none, wi, wo, kWavelengths);
    for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_EQ(a[k], b[k]);
    ASSERT_EQ(bsdf.pdf(ctx, wi, wo, kWavelengths), expected.pdf(none, wi, wo, kWavelengths));
    ASSERT_EQ(bsdf.passThrough(ctx, wi, kWavelengths)[0], expected.passThrough(none, wi, kWavelengths)[0]);
    if (a[0] != bsdf.eval(none, wi, wo, kWavelengths)[0]) ++differing;
  }
  EXPECT_GT(differing, 1000);
}

TEST(BarbuleBSDF, TRTQuadratureIsCloseToAFineOne) {
  // The default node counts against 24 x 8 nodes: relative L1 error of the TRT lobe over the sphere
  // of outgoing directions, per incident direction.
  const BSDFContext ctx;
  BarbuleParameters p = reference(0.58f);
  BarbuleBSDF coarse(p), fine(p, BarbuleBSDF::Role::CameraIncident, BarbuleQuadrature{24, 8, 3});
  PCG32 rng(61);
  std::vector<double> errors;
  for (int i = 0; i < 30; ++i) {
    Vec3 wi = sampleCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    double error = 0.0, total = 0.0;
    for (int j = 0; j < 1000; ++j) {
      Vec3 wo = sampleUniformSphere(Vec2((j + rng.nextFloat()) / 1000.0f, rng.nextFloat()));
      Spectrum a = coarse.evalLobes(ctx, wi, wo, kWavelengths).trt, b = fine.evalLobes(ctx, wi, wo, kWavelengths).trt;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        error += std::abs(a[k] - b[k]) * std::abs(wo.z);
        total += b[k] * std::abs(wo.z);
      }
    }
    if (total > 0.0) errors.push_back(error / total);
  }
  double mean = 0.0, worst = 0.0;
  for (double e : errors) {
    mean += e / errors.size();
    worst = std::max(worst, e);
  }
  std::printf("TRT quadrature (default nodes) vs 24 x 8: relative L1 error mean %.2e, max %.2e\n", mean, worst);
  EXPECT_LT(mean, 1.5e-2);
  EXPECT_LT(worst, 6e-2);
}

namespace {

Properties barbuleProperties(const std::string& type) {
  Properties props;
  props.tag = "bsdf";
  props.type = type;
  return props;
}

}  // namespace

TEST(BarbuleBSDF, FactoriesReadTheReferenceParameters) {
  Properties props = barbuleProperties("barbulebsdfev");
  setString(props, "film_ior", "keratin");
  setString(props, "ext_ior", "air");
  setFloat(props, "height", 0.58f);
  setFloat(props, "b", 0.25f);
  setFloat(props, "phi_0", -0.37f);
  setFloat(props, "phi_1", 2.64f);
  setFloat(props, "mu", -0.35f);
  setFloat(props, "H", 1.25f);
  auto ev = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDFEv(props));
  ASSERT_TRUE(ev);
  props.checkAllUsed();
  EXPECT_EQ(ev->role(), BarbuleBSDF::Role::LightIncident);
  EXPECT_EQ(ev->parameters().height, 0.58f);
  EXPECT_EQ(ev->parameters().filmIOR.b, RefractiveIndex::keratin().b);
  EXPECT_NEAR(ev->parameters().extIOR, 1.000277f, 1e-7f);

  // Defaults (DESIGN.md 5.8), a numeric and a named film index.
  auto plain = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(barbuleProperties("barbulebsdf")));
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->role(), BarbuleBSDF::Role::CameraIncident);
  EXPECT_EQ(plain->parameters().b, 0.25f);
  EXPECT_EQ(plain->parameters().phi0, -0.37f);
  EXPECT_EQ(plain->parameters().phi1, 2.64f);
  EXPECT_EQ(plain->parameters().mu, -0.35f);
  EXPECT_EQ(plain->parameters().H, 1.25f);
  EXPECT_EQ(plain->parameters().height, 0.6f);
  EXPECT_EQ(plain->parameters().filmIOR.a, RefractiveIndex::keratin().a);

  Properties numeric = barbuleProperties("barbulebsdf");
  setFloat(numeric, "film_ior", 1.56f);
  auto constant = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(numeric));
  EXPECT_TRUE(constant->parameters().filmIOR.isConstant());
  EXPECT_EQ(constant->parameters().filmIOR.a, 1.56f);
  Properties named = barbuleProperties("barbulebsdf");
  setString(named, "film_ior", "diamond");
  EXPECT_NEAR(std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(named))->parameters().filmIOR.a, 2.419f, 1e-6f);
}

TEST(BarbuleBSDF, FactoriesRejectInvalidParameters) {
  auto rejects = [](const std::string& name, const std::string& text, float number, bool isString) {
    Properties props = barbuleProperties("barbulebsdf");
    if (isString)
      setString(props, name, text);
    else
      setFloat(props, name, number);
    EXPECT_THROW(makeBarbuleBSDF(props), InputError) << name;
  };
  rejects("film_ior", "unobtainium", 0, true);
  rejects("film_ior", "", 0.9f, false);    // not denser than air
  rejects("ext_ior", "keratin", 0, true);  // the surroundings need a constant index
  rejects("b", "", -0.1f, false);
  rejects("H", "", 0.0f, false);
  rejects("height", "", -0.5f, false);
  rejects("phi_1", "", 4.0f, false);  // arc of more than pi but less than the whole ellipse
  rejects("profile_exponent", "", 1.5f, false);
  for (const auto& [name, value] :
       {std::pair<const char*, int>{"trt_offsets", 0}, {"trt_offsets", 65}, {"trt_angles", 17}}) {
    Properties props = barbuleProperties("barbulebsdf");
    setInt(props, name, value);
    try {
      makeBarbuleBSDF(props);
      ADD_FAILURE() << name << " " << value << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("must number"), std::string::npos) << e.what();
    }
  }
}

TEST(BarbuleBSDF, TheSceneSetsTheTRTQuadrature) {
  // trt_offsets and trt_angles reach the lobe: the plug-in's eval is the one of a BSDF built with
  // that quadrature, and differs from the default's.
  Properties props = barbuleProperties("barbulebsdf");
  setFloat(props, "profile_exponent", 8.0f);
  setInt(props, "trt_offsets", 16);
  setInt(props, "trt_angles", 2);
  auto fromScene = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(props));
  ASSERT_TRUE(fromScene);
  BarbuleParameters p = fromScene->parameters();
  BarbuleBSDF fine(p, BarbuleBSDF::Role::CameraIncident, BarbuleQuadrature{16, 2, 4});
  BarbuleBSDF usual(p, BarbuleBSDF::Role::CameraIncident);
  const BSDFContext ctx;
  int differing = 0;
  for (const Vec3& wi : incidentDirections())
    for (const Vec3& wo : incidentDirections()) {
      const Vec3 out(-wo.x, wo.y, wo.z);
      Spectrum a = fromScene->evalLobes(ctx, wi, out, kWavelengths).trt,
               b = fine.evalLobes(ctx, wi, out, kWavelengths).trt;
      Spectrum c = usual.evalLobes(ctx, wi, out, kWavelengths).trt;
      bool same = true;
      for (int k = 0; k < kSpectrumSamples; ++k) {
        EXPECT_EQ(a[k], b[k]);
        same = same && a[k] == c[k];
      }
      differing += !same;
    }
  EXPECT_GT(differing, 20);
}

// A NaN sample or wavelength indexed the TRT share's nodes with int(NaN) and crashed (clampf let
// NaN through); whatever it draws, it must not read out of bounds.
TEST(BarbuleBSDF, NaNSamplesAndWavelengthsDoNotCrash) {
  // The ellipse and a superellipse, whose numerical solves must end on NaN input too.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Vec3 wi = normalize(Vec3(0.3f, 0.1f, 0.9f));
  const Wavelengths green = Wavelengths::fixed({550.0f, 550.0f, 550.0f, 550.0f});
  for (const BarbuleBSDF& bsdf : {BarbuleBSDF{BarbuleParameters{}}, BarbuleBSDF{squarer(8.0f)}}) {
    for (const Wavelengths& wl : {green, Wavelengths::fixed({nan, nan, nan, nan}), Wavelengths::fixed({0, 0, 0, 0})})
      for (float u1 : {0.5f, nan})
        for (Vec2 u2 : {Vec2(0.5f, 0.5f), Vec2(nan, nan)}) {
          std::optional<BSDFSample> s = bsdf.sample(BSDFContext{}, wi, wl, u1, u2);
          if (s && wl[0] == 550.0f && u1 == 0.5f && u2.x == 0.5f) {
            EXPECT_TRUE(s->weight.isFinite());
          }
        }
    // Degenerate directions end, and give finite values where they are numbers.
    for (const Vec3& w : {Vec3(nan, nan, nan), Vec3(0.0f, 0.0f, 0.0f), Vec3(0.0f, 1.0f, 0.0f)}) {
      const bool numbers = !std::isnan(w.x);
      Spectrum a = bsdf.eval(BSDFContext{}, w, wi, green), b = bsdf.eval(BSDFContext{}, wi, w, green);
      float density = bsdf.pdf(BSDFContext{}, wi, w, green);
      std::optional<BSDFSample> s = bsdf.sample(BSDFContext{}, w, green, 0.5f, Vec2(0.5f, 0.5f));
      if (numbers) {
        EXPECT_TRUE(a.isFinite() && b.isFinite() && std::isfinite(density));
        if (s) {
          EXPECT_TRUE(s->weight.isFinite());
        }
      }
    }
  }
  EXPECT_EQ(clampf(nan, 0.0f, 3.0f), 0.0f);
}

// A layer of no thickness changes nothing: the layered film (transfer matrices, double precision)
// gives the lobes of the cortex alone (the Airy fast path, float) within float rounding; a real
// layer changes them.
TEST(BarbuleBSDF, ALayeredFilmWithAnEmptyLayerIsTheCortexAlone) {
  Properties plainProps = barbuleProperties("barbulebsdf");
  Properties emptyLayer = barbuleProperties("barbulebsdf");
  setString(emptyLayer, "layers", "1.7+0.1i:0");
  Properties realLayer = barbuleProperties("barbulebsdf");
  setString(realLayer, "layers", "1.7+0.1i:0.15");
  auto plain = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(plainProps));
  auto empty = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(emptyLayer));
  auto real = std::dynamic_pointer_cast<BarbuleBSDF>(makeBarbuleBSDF(realLayer));
  ASSERT_EQ(empty->parameters().layersBelow.layers.size(), 1u);
  BSDFContext ctx;
  int changed = 0;
  for (const Vec3& wi : incidentDirections())
    for (const Vec3& wo : {direction(30.0f, 200.0f), direction(10.0f, 180.0f), direction(55.0f, 160.0f)}) {
      const BarbuleBSDF::Lobes a = plain->evalLobes(ctx, wi, wo, kWavelengths);
      const BarbuleBSDF::Lobes b = empty->evalLobes(ctx, wi, wo, kWavelengths);
      const BarbuleBSDF::Lobes c = real->evalLobes(ctx, wi, wo, kWavelengths);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        EXPECT_NEAR(b.reflection[k], a.reflection[k], 2e-5f * (1.0f + a.reflection[k]));
        EXPECT_NEAR(b.trt[k], a.trt[k], 2e-5f * (1.0f + a.trt[k]));
        changed += std::abs(c.reflection[k] - a.reflection[k]) > 1e-3f * a.reflection[k];
      }
    }
  EXPECT_GT(changed, 0);
  Properties bad = barbuleProperties("barbulebsdf");
  setString(bad, "layers", "eumelanin:0.1");
  EXPECT_THROW(makeBarbuleBSDF(bad), InputError);
}
