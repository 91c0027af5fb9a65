#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include "core/illuminant.h"
#include "core/rgb_spectrum_table.h"
#include "core/rng.h"
#include "core/spectrum.h"

using namespace columba;

namespace {
// Linear RGB of a spectrum lit by D65, integrated on a 1 nm grid.
Vec3 rgbUnderD65(const RGBSpectrum& s) {
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * (s.eval(l) * d65(l));
  return xyzToLinearRGB(xyz / cieYIntegral());
}

float largestDifference(const Vec3& a, const Vec3& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}
}  // namespace

TEST(RGBSpectrumTable, TabulatedSpectraKeepTheirColour) {
  // Random colours over six decades of brightness, saturated ones among them: the tabulated
  // spectrum's colour under D65 is the colour to 1 % of its largest component (bilinear
  // coefficients between nodes; measured largest error 0.2 %), and it never goes negative.
  PCG32 rng(11, 3);
  float worst = 0.0f;
  for (int n = 0; n < 400; ++n) {
    Vec3 c(rng.nextFloat(), rng.nextFloat(), rng.nextFloat());
    if (n % 4 == 0) c[n % 3] = 0.0f;  // a primary missing entirely
    c *= std::pow(10.0f, 6.0f * rng.nextFloat() - 3.0f);
    const float m = std::max({c.x, c.y, c.z});
    const RGBSpectrum s = tabulatedRGBSpectrum(c);
    EXPECT_FLOAT_EQ(s.scale, 2.0f * m);
    const float error = largestDifference(rgbUnderD65(s), c) / m;
    worst = std::max(worst, error);
    EXPECT_LT(error, 0.01f) << c.x << ", " << c.y << ", " << c.z;
    for (float l = kLambdaMin; l <= kLambdaMax; l += 10.0f) EXPECT_GE(s.eval(l), 0.0f);
  }
  RecordProperty("largest_relative_error", std::to_string(worst));
}

TEST(RGBSpectrumTable, GreyIsNearlyFlatAndBlackIsZero) {
  // Grey is fitted too: D65's colour through the fitted colour matching functions is white only
  // to about 1 %, so grey's spectrum is flat to that.
  const RGBSpectrum grey = tabulatedRGBSpectrum(Vec3(3.0f, 3.0f, 3.0f));
  for (float l = kLambdaMin; l <= kLambdaMax; l += 10.0f) EXPECT_NEAR(grey.eval(l), 3.0f, 0.03f);
  const RGBSpectrum black = tabulatedRGBSpectrum(Vec3(0.0f, -1.0f, 0.0f));
  for (float l = kLambdaMin; l <= kLambdaMax; l += 10.0f) EXPECT_EQ(black.eval(l), 0.0f);
}

TEST(RGBSpectrumTable, TheTableAgreesWithAFitOfItsOwn) {
  // Between the nodes the table interpolates; a fit made for the colour itself (fitRGBSpectrum,
  // unbounded, the same scaling) gives the same spectrum to within the interpolation.
  for (Vec3 c : {Vec3(0.2f, 0.8f, 0.1f), Vec3(5.0f, 1.0f, 0.3f), Vec3(0.01f, 0.02f, 0.05f)}) {
    const RGBSpectrum table = tabulatedRGBSpectrum(c), fit = fitRGBSpectrum(c, true);
    for (float l = kLambdaMin; l <= kLambdaMax; l += 5.0f)
      EXPECT_NEAR(table.eval(l), fit.eval(l), 0.02f * fit.scale) << l;
  }
}

TEST(RGBSpectrumTable, AFitFromANeighboursCoefficientsMatchesOneFromGrey) {
  const Vec3 target(0.45f, 0.2f, 0.05f);
  const std::array<float, 3> fromGrey = fitSigmoidCoefficients(target);
  const std::array<float, 3> fromNeighbour =
      fitSigmoidCoefficients(target, fitSigmoidCoefficients(Vec3(0.5f, 0.25f, 0.1f)));
  const RGBSpectrum a{fromGrey, 1.0f}, b{fromNeighbour, 1.0f};
  EXPECT_LT(largestDifference(rgbUnderD65(a), target), 2e-5f);
  EXPECT_LT(largestDifference(rgbUnderD65(b), target), 2e-5f);
}

TEST(RGBSpectrumTable, EveryNodeOfTheTableKeepsItsColour) {
  // At ratios j / 63 and k / 63 the lookup returns a node's own coefficients (or, on the last row
  // and column, its neighbour's weighted fully): every fit of the table, each started from its
  // neighbour's, is checked, the saturated edges (a ratio of 0) among them.
  float worst = 0.0f;
  Vec3 worstColour;
  for (int channel = 0; channel < 3; ++channel)
    for (int j = 0; j < 64; ++j)
      for (int k = 0; k < 64; ++k) {
        Vec3 c;
        c[channel] = 1.0f;
        c[(channel + 1) % 3] = float(j) / 63.0f;
        c[(channel + 2) % 3] = float(k) / 63.0f;
        const float error = largestDifference(rgbUnderD65(tabulatedRGBSpectrum(c)), c);
        if (error > worst) worst = error, worstColour = c;
      }
  EXPECT_LT(worst, 0.01f) << worstColour.x << ", " << worstColour.y << ", " << worstColour.z;
  RecordProperty("largest_node_error", std::to_string(worst));
}
