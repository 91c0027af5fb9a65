// The production's shortcuts outside core/fast_math.h (whose functions test_fast_math.cpp sweeps)
// against plain double-precision computations over their whole input ranges: the barbule's
// longitudinal-angle constants, the closed forms of LongitudinalDensity (mean angle, shadowing,
// and meanLongitudinalAngles' unclipped constant) against the reference's numerical moments, and
// the melanin table's cell lookup against a plain interpolation of the published table. Each
// bound is a small factor above the measured maximum (in the comments).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>
#include "barbule/normals.h"
#include "core/fast_math.h"
#include "optics/melanin.h"
#include "support/reference_barbule.h"

using namespace columba;

namespace {

// meanLongitudinalAngles (its unclipped constant 0.00205703 and LongitudinalDensity::mean) and
// LongitudinalDensity::shadowing against the reference's numerical moments, absolute in radians
// and absolute. Where the range is clipped, the mass F(thetaMax) - F(thetaMin) with
// F = A sin - B cos is a difference of two cosines near 1 when |B| >> A and keeps about 5 digits in
// float. Measured 2.3e-6 rad and 2.4e-5.
constexpr double kLongitudinalMeanBound = 5e-6, kShadowingBound = 1e-4;
// LongitudinalDensity::angleAtMass: the mass below its angle against the mass asked for (a
// backward error: near a clipped end asin's argument is close to -1 or 1, where float rounding
// moves the angle itself by up to 4e-4 rad, but not the mass below it), and its cosine and sine
// against the angle's. Measured 3.4e-5 and 1.8e-7.
constexpr double kLongitudinalMassBound = 1e-4, kLongitudinalCosSinBound = 1e-6;
// melaninReflectance's cell lookup against a plain linear interpolation of the published table.
// Measured 9.7e-9.
constexpr double kMelaninBound = 5e-8;

}  // namespace

TEST(FastMathReference, BarbuleThetaDConstants) {
  double thetaD = 0.025 * M_PI;
  EXPECT_EQ(kBarbuleThetaD, float(thetaD));
  EXPECT_NEAR(kSinBarbuleThetaD, std::sin(thetaD), 0x1p-24 * std::sin(thetaD));
  EXPECT_NEAR(kCosBarbuleThetaD, std::cos(thetaD), 0x1p-24);
  EXPECT_NEAR(kTanBarbuleThetaD, std::tan(thetaD), 0x1p-24 * std::tan(thetaD));
}

TEST(FastMathReference, LongitudinalMeanAndShadowingOverAllDirections) {
  // Every direction (A, B) = (cos a, sin a) seen by a normal it faces in-plane (A > 0): unclipped
  // (the closed-form constant) and clipped ranges alike; the scale of (A, B) must not matter.
  double meanError = 0.0, shadowError = 0.0;
  for (int i = 1; i < 200000; ++i) {
    double a = -M_PI / 2 + M_PI * i / 200000;
    for (double scale : {1.0, 0.03}) {
      float A = float(scale * std::cos(a)), B = float(scale * std::sin(a));
      reference::LongitudinalMoments m = reference::longitudinalMoments(A, B);
      if (!(m.mass > 0.0)) continue;
      FloatLanes mean = meanLongitudinalAngles(FloatLanes{A, A, A, A}, B);
      meanError = std::max(meanError, std::abs(mean[0] - m.mean));
      meanError = std::max(meanError, double(std::abs(LongitudinalDensity(A, B).mean() - m.mean)));
      shadowError = std::max(shadowError, std::abs(longitudinalShadowing(A, B) - m.shadowing()));
    }
  }
  std::printf("longitudinal mean: max abs error %.2e rad; shadowing %.2e\n", meanError, shadowError);
  EXPECT_LT(meanError, kLongitudinalMeanBound);
  EXPECT_LT(shadowError, kShadowingBound);
}

TEST(FastMathReference, LongitudinalAngleAtMassIsTheInverseCdfWithItsCosineAndSine) {
  // Over every direction and the whole mass: the mass below the angle returned, in double, against
  // the mass asked for (relative to the whole mass: the inverse CDF's error in u), and its cosine
  // and sine against those of that angle.
  double massError = 0.0, cosSinError = 0.0;
  for (int i = 1; i < 20000; ++i) {
    double a = -M_PI / 2 + M_PI * i / 20000;
    float A = float(std::cos(a)), B = float(std::sin(a));
    LongitudinalDensity density(A, B);
    if (!(density.mass() > 0.0f)) continue;
    auto primitive = [&](double theta) { return A * std::sin(theta) - B * std::cos(theta); };
    const double below = primitive(density.thetaMin()), whole = primitive(density.thetaMax()) - below;
    for (int k = 0; k <= 16; ++k) {
      const double u = k / 16.0;
      AngleCosSin angle = density.angleAtMass(float(u * whole));
      const double theta = std::clamp(double(angle.theta), double(density.thetaMin()), double(density.thetaMax()));
      massError = std::max(massError, std::abs((primitive(theta) - below) / whole - u));
      cosSinError = std::max({cosSinError, std::abs(angle.cosTheta - std::cos(double(angle.theta))),
                              std::abs(angle.sinTheta - std::sin(double(angle.theta)))});
    }
  }
  std::printf("longitudinal angle at mass: max error in u %.2e; cosine and sine %.2e\n", massError, cosSinError);
  EXPECT_LT(massError, kLongitudinalMassBound);
  EXPECT_LT(cosSinError, kLongitudinalCosSinBound);
}

TEST(FastMathReference, MelaninLookupIsTheLinearInterpolation) {
  std::ifstream file(std::string(COLUMBA_SHARED_DIR) + "/reference/data/melanin.r.spd");
  if (!file) GTEST_SKIP() << "the published melanin table is not available";
  std::vector<std::pair<double, double>> table;
  double l, r;
  while (file >> l >> r) table.emplace_back(l, r);
  ASSERT_GT(table.size(), 100u);
  double worst = 0.0;
  size_t j = 1;
  for (int i = 0; i <= 800000; ++i) {
    float lambda = float(200.0 + 750.0 * i / 800000);
    double expected;
    if (lambda <= table.front().first)
      expected = table.front().second;
    else if (lambda >= table.back().first)
      expected = table.back().second;
    else {
      while (table[j].first < lambda) ++j;
      double t = (lambda - table[j - 1].first) / (table[j].first - table[j - 1].first);
      expected = table[j - 1].second + t * (table[j].second - table[j - 1].second);
    }
    worst = std::max(worst, std::abs(melaninReflectance(lambda) - expected));
  }
  std::printf("melanin lookup vs linear interpolation of the published table: max abs error %.2e\n", worst);
  EXPECT_LT(worst, kMelaninBound);
}
