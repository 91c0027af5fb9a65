#include <gtest/gtest.h>

#include "core/spectrum.h"

using namespace columba;

TEST(Spectrum, FlatSpectrumIsNeutralGrey) {
  // Integrate a flat spectrum of 1 exactly on a 1 nm grid.
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l);
  Vec3 rgb = xyzToLinearRGB(xyz / cieYIntegral());
  EXPECT_NEAR(rgb.x, 1.0f, 1e-4f);
  EXPECT_NEAR(rgb.y, 1.0f, 1e-4f);
  EXPECT_NEAR(rgb.z, 1.0f, 1e-4f);
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

TEST(Spectrum, RGBUpsamplingRoundTrips) {
  for (Vec3 target : {Vec3(0.132f, 0.12f, 0.12f), Vec3(0.6f, 0.55f, 0.72f), Vec3(0.2f, 0.7f, 0.3f), Vec3(0.9f, 0.1f, 0.1f)}) {
    SpectralDistribution s = SpectralDistribution::fromRGB(target, false);
    Vec3 xyz(0, 0, 0);
    for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * s.eval(l);
    Vec3 rgb = xyzToLinearRGB(xyz / cieYIntegral());
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
  SpectralDistribution s = SpectralDistribution::fromRGB(Vec3(10.0f, 5.0f, 2.0f), true);
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * s.eval(l);
  Vec3 rgb = xyzToLinearRGB(xyz / cieYIntegral());
  EXPECT_NEAR(rgb.x, 10.0f, 0.1f);
  EXPECT_NEAR(rgb.y, 5.0f, 0.1f);
  EXPECT_NEAR(rgb.z, 2.0f, 0.1f);
}

TEST(Spectrum, PiecewiseLinearInterpolatesAndClampsAtEnds) {
  auto s = SpectralDistribution::piecewiseLinear({400, 500, 600}, {0.2f, 0.6f, 1.0f});
  EXPECT_FLOAT_EQ(s.eval(450), 0.4f);
  EXPECT_FLOAT_EQ(s.eval(350), 0.2f);
  EXPECT_FLOAT_EQ(s.eval(700), 1.0f);
  EXPECT_THROW(SpectralDistribution::piecewiseLinear({500, 400}, {1, 1}), std::invalid_argument);
}
