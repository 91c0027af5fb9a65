// CIELAB and CIEDE2000 for the human observer: the white, a mid grey, and pairs of the test data
// Sharma, Wu & Dalal (2005, Color Res Appl 30:21-30, Table 1) published for CIEDE2000.
#include <gtest/gtest.h>

#include <cmath>

#include "vision/human_colour_difference.h"

using namespace columba;

TEST(HumanColourDifference, WhiteAndGreyHaveTheirLightness) {
  const CIELab white = labFromLinearRGB(Vec3(1, 1, 1));
  EXPECT_NEAR(white.L, 100.0, 1e-4);
  EXPECT_NEAR(white.a, 0.0, 1e-4);
  EXPECT_NEAR(white.b, 0.0, 1e-4);
  // L* = 116 Y^(1/3) - 16 above the linear toe.
  const CIELab grey = labFromLinearRGB(Vec3(0.18f, 0.18f, 0.18f));
  EXPECT_NEAR(grey.L, 116.0 * std::cbrt(0.18) - 16.0, 1e-3);
  EXPECT_NEAR(grey.a, 0.0, 1e-3);
  EXPECT_NEAR(grey.b, 0.0, 1e-3);
  // Saturated red lies at positive a*.
  EXPECT_GT(labFromLinearRGB(Vec3(1, 0, 0)).a, 50.0);
}

TEST(HumanColourDifference, CIEDE2000MatchesPublishedPairs) {
  EXPECT_NEAR(deltaE2000({50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}), 2.0425, 1e-4);  // pair 1
  EXPECT_NEAR(deltaE2000({50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}), 2.3669, 1e-4);              // pair 7
  EXPECT_NEAR(deltaE1976({50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}), std::sqrt(5.0), 1e-9);
  EXPECT_EQ(deltaE2000({40.0, 10.0, -5.0}, {40.0, 10.0, -5.0}), 0.0);
}
