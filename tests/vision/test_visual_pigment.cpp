#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "vision/oil_droplet.h"
#include "vision/spectral_grid.h"
#include "vision/visual_pigment.h"

using namespace columba;

namespace {
// The wavelength of the largest sample of f on a 0.1 nm grid over 300-830 nm.
double peakWavelength(double (*f)(double, double, bool), double lambdaMax, bool beta) {
  double best = 0.0, bestWl = 0.0;
  for (double wl = 300.0; wl <= 830.0; wl += 0.1) {
    double v = f(lambdaMax, wl, beta);
    if (v > best) best = v, bestWl = wl;
  }
  return bestWl;
}
double alphaOnly(double lambdaMax, double wl, bool) { return govardovskiiAlphaBand(lambdaMax, wl); }
}  // namespace

TEST(VisionPigment, TemplatePeaksAtLambdaMax) {
  // The alpha band peaks at its lambdaMax, with a value of about 1, for every pigment a bird has.
  for (double lambdaMax : {360.0, 371.0, 409.0, 424.0, 448.0, 458.0, 502.0, 505.0, 563.0, 567.0}) {
    EXPECT_NEAR(peakWavelength(alphaOnly, lambdaMax, false), lambdaMax, 1.0) << lambdaMax;
    EXPECT_NEAR(govardovskiiAlphaBand(lambdaMax, lambdaMax), 1.0, 0.01) << lambdaMax;
    // The beta band, 0.26 high at 189 + 0.315 lambdaMax, pulls the peak of the whole template towards
    // it: by under 1 nm from 371 nm up, by 1.2 nm for a 360 nm pigment, whose bands lie closest.
    EXPECT_NEAR(peakWavelength(govardovskiiA1, lambdaMax, true), lambdaMax, lambdaMax < 370.0 ? 1.5 : 1.0) << lambdaMax;
  }
}

TEST(VisionPigment, BetaBandConstants) {
  // At its own peak, 189 + 0.315 * 500 = 346.5 nm, the beta band of a 500 nm pigment is 0.26; one
  // width (-40.5 + 0.195 * 500 = 57 nm) away it has fallen by exp(-1).
  EXPECT_NEAR(govardovskiiBetaBand(500.0, 346.5), 0.26, 1e-12);
  EXPECT_NEAR(govardovskiiBetaBand(500.0, 346.5 + 57.0), 0.26 * std::exp(-1.0), 1e-12);
  EXPECT_DOUBLE_EQ(govardovskiiA1(500.0, 400.0, false), govardovskiiAlphaBand(500.0, 400.0));
}

TEST(VisionPigment, AbsorbanceOnAGridHasPeakOne) {
  SpectralGrid grid = visionGrid();
  EXPECT_EQ(grid.count, 531u);
  EXPECT_DOUBLE_EQ(grid.lastNm(), 830.0);
  std::vector<float> s = visualPigmentAbsorbance(grid, 448.0);
  float peak = 0.0f;
  std::size_t at = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] > peak) peak = s[i], at = i;
  EXPECT_FLOAT_EQ(peak, 1.0f);
  EXPECT_NEAR(grid.wavelength(at), 448.0, 1.0);
}

TEST(VisionOilDroplet, HalfTransmittedAtItsMidpoint) {
  // The model's transmittance at lambdaMid = lambdaCut + 0.5 / bMid is exp(-exp(-2.89 / 2 + 1.08))
  // = exp(-exp(-0.365)) = 0.4995: one half, to the model's rounding of its constants.
  for (double cut : {413.0, 507.0, 572.0}) {
    OilDroplet d = oilDropletFromCutAndMid(cut, cut + 20.0);
    EXPECT_DOUBLE_EQ(oilDropletMidpoint(d), cut + 20.0);
    EXPECT_NEAR(oilDropletTransmission(d, cut + 20.0), 0.5, 1e-3);
    EXPECT_NEAR(oilDropletTransmission(d, cut + 20.0), std::exp(-std::exp(-0.365)), 1e-12);
    // A long-pass filter: dark well below the cut-off, clear well above it.
    EXPECT_LT(oilDropletTransmission(d, cut - 20.0), 1e-3);
    EXPECT_GT(oilDropletTransmission(d, cut + 100.0), 0.99);
  }
}

TEST(VisionOilDroplet, TypesFollowHartAndVorobyevRegressions) {
  // lambdaMid = 0.99 * 413 + 24.38 = 433.25 nm for a C droplet cut at 413 nm, so bMid = 0.5 / 20.25.
  auto c = oilDropletOfType(OilDropletType::C, 413.0);
  ASSERT_TRUE(c);
  EXPECT_NEAR(oilDropletMidpoint(*c), 433.25, 1e-9);
  EXPECT_NEAR(c->bMidPerNm, 0.5 / 20.25, 1e-12);
  EXPECT_NEAR(oilDropletMidpoint(*oilDropletOfType(OilDropletType::Y, 507.0)), 0.90 * 507.0 + 70.03, 1e-9);
  EXPECT_NEAR(oilDropletMidpoint(*oilDropletOfType(OilDropletType::R, 572.0)), 0.99 * 572.0 + 28.65, 1e-9);
  EXPECT_NEAR(oilDropletMidpoint(*oilDropletOfType(OilDropletType::P, 420.0)), 0.96 * 420.0 + 33.57, 1e-9);
  EXPECT_FALSE(oilDropletOfType(OilDropletType::T, 330.0));
  EXPECT_EQ(parseOilDropletType("Y"), OilDropletType::Y);
  EXPECT_FALSE(parseOilDropletType("y"));
  EXPECT_THROW(oilDropletFromCutAndMid(500.0, 500.0), std::invalid_argument);
}
