// The production's shortcuts outside core/fast_math.h (whose functions test_fast_math.cpp sweeps)
// against plain double-precision computations over their whole input ranges: the barbule's
// longitudinal-angle constants, the closed forms of LongitudinalDensity (mean angle, shadowing,
// and meanLongitudinalAngles' unclipped constant) against the reference's numerical moments, and
// the melanin table's cell lookup against a plain interpolation of the published table. Each
// bound is a small factor above the measured maximum (in the comments).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>
#include "bsdfs/barbule_normals.h"
#include "core/fast_math.h"
#include "optics/melanin.h"
#include "reference_barbule.h"

using namespace columba;

namespace {

// meanLongitudinalAngles (its unclipped constant 0.00205703 and LongitudinalDensity::mean) and
// LongitudinalDensity::shadowing against the reference's numerical moments, absolute in radians
// and absolute. Where the range is clipped, the mass F(thetaMax) - F(thetaMin) with
// F = A sin - B cos is a difference of two cosines near 1 when |B| >> A and keeps about 5 digits in
// float. Measured 2.3e-6 rad and 2.4e-5.
constexpr double kLongitudinalMeanBound = 5e-6, kShadowingBound = 1e-4;
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
