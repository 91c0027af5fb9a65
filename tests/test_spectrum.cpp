#include <gtest/gtest.h>

#include "core/illuminant.h"
#include "core/spectrum.h"

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

TEST(Spectrum, FlatSpectrumIsNotWhiteBalanced) {
  // No white balance (as Mitsuba): an equal-energy spectrum is pinkish, red above blue.
  Vec3 rgb = rgbOf(SpectralDistribution::constant(1.0f), false);
  EXPECT_GT(rgb.x, 1.1f);
  EXPECT_LT(rgb.z, 0.95f);
}

TEST(Spectrum, VisibleWavelengthPdfIntegratesToOneAndMatchesSampling) {
  double integral = 0;
  for (float l = kLambdaMin; l < kLambdaMax; l += 0.25f) integral += visibleWavelengthPdf(l + 0.125f) * 0.25;
  EXPECT_NEAR(integral, 1.0, 2e-3);
  // The sampling routine inverts the CDF: the fraction of samples below 538 nm is the CDF there.
  double cdf = 0;
  for (float l = kLambdaMin; l < 538.0f; l += 0.25f) cdf += visibleWavelengthPdf(l + 0.125f) * 0.25;
  int below = 0, n = 100000;
  for (int i = 0; i < n; ++i) below += sampleVisibleWavelength((i + 0.5f) / n) < 538.0f;
  EXPECT_NEAR(double(below) / n, cdf, 2e-3);
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
