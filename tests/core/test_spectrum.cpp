#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include "core/illuminant.h"
#include "core/rng.h"
#include "core/spectrum.h"
#include "support/chi_square.h"

using namespace columba;

namespace {
// Linear RGB of a spectrum, integrated exactly on a 1 nm grid.
Vec3 rgbOf(const SpectralDistribution& s, bool litByD65) {
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * (s.eval(l) * (litByD65 ? d65(l) : 1.0f));
  return xyzToLinearRGB(xyz / cieYIntegral());
}
}  // namespace

TEST(Spectrum, D65IsWhiteWithUnitLuminance) {
  // The plain sRGB matrix has D65 as its white: D65 of luminance 1 is (1, 1, 1) up to the
  // colour matching functions' fit.
  Vec3 rgb = rgbOf(SpectralDistribution::constant(1.0f), true);
  EXPECT_NEAR(rgb.x, 1.0f, 0.01f);
  EXPECT_NEAR(rgb.y, 1.0f, 0.01f);
  EXPECT_NEAR(rgb.z, 1.0f, 0.01f);
  // Its chromaticity is CIE's (x, y) = (0.31272, 0.32903) and its luminance exactly 1.
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * d65(l);
  xyz = xyz / cieYIntegral();
  EXPECT_NEAR(xyz.y, 1.0f, 1e-5f);
  EXPECT_NEAR(xyz.x / (xyz.x + xyz.y + xyz.z), 0.31272f, 0.002f);
  EXPECT_NEAR(xyz.y / (xyz.x + xyz.y + xyz.z), 0.32903f, 0.002f);
  // Published values of the table (CIE 15:2004 Table T.1), relative to 560 nm.
  EXPECT_NEAR(d65(460.0f) / d65(560.0f), 1.17812f, 1e-5f);
  EXPECT_NEAR(d65(702.5f) / d65(560.0f), 0.5f * (0.716091f + 0.72979f), 1e-5f);
}

TEST(Spectrum, AtAPathsWavelengthsD65AndSpectraAreTheirValuesAtEach) {
  // The four-lane lookups against the scalar ones, bit for bit, including wavelengths beyond the
  // table and at its ends.
  const std::vector<SpectralDistribution> spectra = {
      SpectralDistribution::constant(0.7f).timesD65(), SpectralDistribution::fromRGB(Vec3(0.2f, 0.5f, 0.9f), false),
      SpectralDistribution::fromRGB(Vec3(0.8f, 0.3f, 0.1f), false).timesD65()};
  PCG32 rng(4);
  for (int i = 0; i < 10000; ++i) {
    Wavelengths wl = Wavelengths::fixed(
        {250.0f + 650.0f * rng.nextFloat(), 300.0f, 830.0f, kLambdaMin + (kLambdaMax - kLambdaMin) * rng.nextFloat()});
    Spectrum lanes = d65(wl);
    for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_EQ(lanes[k], d65(wl[k])) << wl[k];
    for (const SpectralDistribution& s : spectra) {
      Spectrum values = s.sample(wl);
      for (int k = 0; k < kSpectrumSamples; ++k) ASSERT_EQ(values[k], s.eval(wl[k])) << wl[k];
    }
  }
}

TEST(Spectrum, FlatSpectrumIsNotWhiteBalanced) {
  // No white balance (as Mitsuba): an equal-energy spectrum is pinkish, red above blue.
  Vec3 rgb = rgbOf(SpectralDistribution::constant(1.0f), false);
  EXPECT_GT(rgb.x, 1.1f);
  EXPECT_LT(rgb.z, 0.95f);
}

TEST(Spectrum, VisibleWavelengthPdfIntegratesToOneAndMatchesSampling) {
  const WavelengthDensity visible = WavelengthDensity::Visible;
  double integral = 0;
  for (float l = kLambdaMin; l < kLambdaMax; l += 0.25f) integral += wavelengthPdf(l + 0.125f, visible) * 0.25;
  EXPECT_NEAR(integral, 1.0, 2e-3);
  // The sampling routine inverts the CDF: the fraction of samples below 538 nm is the CDF there.
  double cdf = 0;
  for (float l = kLambdaMin; l < 538.0f; l += 0.25f) cdf += wavelengthPdf(l + 0.125f, visible) * 0.25;
  int below = 0, n = 100000;
  for (int i = 0; i < n; ++i) below += sampleWavelength((i + 0.5f) / n, visible) < 538.0f;
  EXPECT_NEAR(double(below) / n, cdf, 2e-3);
  // pbrt-v4's density 0.0039398042 / cosh^2(0.0072 (lambda - 538)), up to the table's steps.
  for (float l : {400.0f, 538.0f, 700.0f})
    EXPECT_NEAR(wavelengthPdf(l, visible), 0.0039398042 / std::pow(std::cosh(0.0072 * (l - 538.0)), 2), 2e-5) << l;
}

TEST(Spectrum, EachWavelengthDensityIsWhatItsSamplesFollow) {
  // Chi-square of 200,000 hero wavelengths (with the other three) over 94 bins of 5 nm against
  // the reported pdf integrated over each bin.
  for (WavelengthDensity density : {WavelengthDensity::RGBMatching, WavelengthDensity::Visible}) {
    constexpr int kBins = 94;
    const float binWidth = (kLambdaMax - kLambdaMin) / kBins;
    std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
    PCG32 rng(7);
    const int n = 50000;
    for (int i = 0; i < n; ++i) {
      Wavelengths wl = Wavelengths::sample(rng.nextFloat(), density);
      for (int k = 0; k < kSpectrumSamples; ++k) {
        observed[std::clamp(int((wl[k] - kLambdaMin) / binWidth), 0, kBins - 1)] += 1.0;
        EXPECT_NEAR(wl.pdf[k], wavelengthPdf(wl[k], density), 0.02f * wl.pdf[k])
            << wl[k];  // a neighbouring segment at an end
      }
    }
    for (int b = 0; b < kBins; ++b)
      for (int j = 0; j < 200; ++j)
        expected[b] += wavelengthPdf(kLambdaMin + (b + (j + 0.5f) / 200) * binWidth, density) * binWidth / 200 *
                       (n * kSpectrumSamples);
    columba::testing::ChiSquareResult r = columba::testing::chiSquareTest(observed, expected);
    EXPECT_GT(r.pValue, 1e-3) << r.message;
  }
}

TEST(Spectrum, RGBMatchingDensityFollowsTheColourMatchingFunctions) {
  const WavelengthDensity rgb = WavelengthDensity::RGBMatching;
  // Every wavelength can be drawn; blue, where luminance is low, is drawn more often than pbrt's
  // visible density draws it, and the middle of the range at a similar rate.
  for (float l = kLambdaMin; l <= kLambdaMax; l += 5.0f) EXPECT_GT(wavelengthPdf(l, rgb), 0.0f) << l;
  EXPECT_GT(wavelengthPdf(445.0f, rgb), 1.5f * wavelengthPdf(445.0f, WavelengthDensity::Visible));
  // Its shape: |r| + |g| + |b| of the linear-sRGB matching functions plus 1 % of the peak, here
  // from the fitted CIE functions, normalised over the range.
  auto shape = [](float l) {
    Vec3 c = xyzToLinearRGB(cieXYZFit(l));
    return std::abs(c.x) + std::abs(c.y) + std::abs(c.z);
  };
  double peak = 0.0, total = 0.0;
  for (float l = kLambdaMin; l <= kLambdaMax; l += 0.5f) peak = std::max(peak, double(shape(l)));
  for (float l = kLambdaMin; l < kLambdaMax; l += 0.5f) total += (shape(l + 0.25f) + 0.01 * peak) * 0.5;
  // Compared over 30 nm windows: the table's density is constant over each of its 1024 pieces, which
  // span up to 12 nm where the density is low.
  for (float l : {410.0f, 440.0f, 520.0f, 600.0f, 680.0f}) {
    double table = 0.0, expected = 0.0;
    for (float x = l; x < l + 30.0f; x += 0.1f) {
      table += wavelengthPdf(x + 0.05f, rgb) * 0.1;
      expected += (shape(x + 0.05f) + 0.01 * peak) / total * 0.1;
    }
    EXPECT_NEAR(table, expected, 0.02 * expected) << l;
  }
}

TEST(Spectrum, RGBEstimateIsUnbiasedUnderEitherDensity) {
  // The mean of spectrumToRGB over stratified hero wavelengths is the colour integrated on the 1 nm
  // grid, for a smooth reflectance under D65.
  SpectralDistribution s = SpectralDistribution::fromRGB(Vec3(0.2f, 0.5f, 0.8f), false).timesD65();
  Vec3 exact = rgbOf(s, false);
  for (WavelengthDensity density : {WavelengthDensity::RGBMatching, WavelengthDensity::Visible}) {
    Vec3 sum(0, 0, 0);
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      Wavelengths wl = Wavelengths::sample((i + 0.5f) / n, density);
      sum += spectrumToRGB(s.sample(wl), wl);
    }
    Vec3 mean = sum / float(n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], exact[c], 3e-3f * exact[c] + 1e-4f) << c;
  }
}

TEST(Spectrum, RGBUpsamplingRoundTripsUnderD65) {
  // A reflectance's colour is the colour it has under D65 (Jakob & Hanika; Mitsuba).
  for (Vec3 target :
       {Vec3(0.132f, 0.12f, 0.12f), Vec3(0.6f, 0.55f, 0.72f), Vec3(0.2f, 0.7f, 0.3f), Vec3(0.9f, 0.1f, 0.1f)}) {
    SpectralDistribution s = SpectralDistribution::fromRGB(target, false);
    Vec3 rgb = rgbOf(s, true);
    EXPECT_NEAR(rgb.x, target.x, 0.01f);
    EXPECT_NEAR(rgb.y, target.y, 0.01f);
    EXPECT_NEAR(rgb.z, target.z, 0.01f);
    for (float l = kLambdaMin; l <= kLambdaMax; l += 10.0f) {
      EXPECT_GE(s.eval(l), 0.0f);
      EXPECT_LE(s.eval(l), 1.0f);
    }
  }
}

TEST(Spectrum, EmissionRGBAboveOneKeepsItsColour) {
  // An emitted colour is the upsampled colour times D65.
  SpectralDistribution s = SpectralDistribution::fromRGB(Vec3(10.0f, 5.0f, 2.0f), true).timesD65();
  Vec3 rgb = rgbOf(s, false);
  EXPECT_NEAR(rgb.x, 10.0f, 0.1f);
  EXPECT_NEAR(rgb.y, 5.0f, 0.1f);
  EXPECT_NEAR(rgb.z, 2.0f, 0.1f);
  EXPECT_FALSE(s.isConstant());
}

TEST(Spectrum, PiecewiseLinearInterpolatesAndClampsAtEnds) {
  auto s = SpectralDistribution::piecewiseLinear({400, 500, 600}, {0.2f, 0.6f, 1.0f});
  EXPECT_FLOAT_EQ(s.eval(450), 0.4f);
  EXPECT_FLOAT_EQ(s.eval(350), 0.2f);
  EXPECT_FLOAT_EQ(s.eval(700), 1.0f);
  EXPECT_THROW(SpectralDistribution::piecewiseLinear({500, 400}, {1, 1}), std::invalid_argument);
}
