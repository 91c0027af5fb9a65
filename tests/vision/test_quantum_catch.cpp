#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "vision/colour_distance.h"
#include "vision/observer.h"
#include "vision/quantum_catch.h"

using namespace columba;

namespace {
// The blue tit's pigments without their oil droplets: each cone's sensitivity is its template's.
Observer pigmentsOnly() {
  ObserverDefinition d;
  d.name = "pigments";
  for (double lambdaMax : {371.0, 448.0, 502.0, 563.0}) d.cones.push_back({"c", lambdaMax, {}, false});
  d.noise = {{1, 2, 2, 4}, 0.1, 3, 0.1};
  return makeObserver(d);
}

std::vector<float> line(const SpectralGrid& grid, double wl) {
  std::vector<float> r(grid.count, 0.0f);
  r[std::size_t((wl - grid.firstNm) / grid.stepNm + 0.5)] = 1.0f;
  return r;
}
}  // namespace

TEST(VisionQuantumCatch, EqualQuantumCatchesAreTheSensitivityIntegrals) {
  // R = 1 under I = 1 photon per nm: Q_i is the integral of S_i, which is 1 for area-normalised cones.
  Observer o = namedObserver("bluetit");
  std::vector<float> ones = equalQuantumSpectrum(o.grid);
  ConeCatches q = quantumCatches(o, ones, ones);
  ASSERT_EQ(q.chromatic.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(q.chromatic[i], integrateOnGrid(o.grid, o.sensitivities[i]), 1e-9);
    EXPECT_NEAR(q.chromatic[i], 1.0, 1e-5);
  }
  // Twice the light, twice the catch.
  ConeCatches q2 = quantumCatches(o, ones, equalQuantumSpectrum(o.grid, 2.0f));
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(q2.chromatic[i], 2.0 * q.chromatic[i], 1e-9);
}

TEST(VisionQuantumCatch, GreyCardAfterVonKriesGivesEqualCatches) {
  // A spectrally flat 18 % grey, adapted to an ideal white under the same light: q_i = 0.18 for every
  // cone whatever the illuminant, and relative catches of 1/4 each.
  Observer o = namedObserver("bluetit");
  std::vector<float> grey(o.grid.count, 0.18f);
  std::vector<float> light = tabulateOnGrid(o.grid, [](double wl) { return 0.5 + wl / 1000.0; });
  ConeCatches q = adaptedQuantumCatches(o, grey, light);
  for (double v : q.chromatic) EXPECT_NEAR(v, 0.18, 1e-6);
  for (double v : relativeCatches(q.chromatic)) EXPECT_NEAR(v, 0.25, 1e-6);
  // Adapted to the grey card itself, the card gives catches of 1.
  for (double v : adaptedQuantumCatches(o, grey, light, grey).chromatic) EXPECT_NEAR(v, 1.0, 1e-6);
}

TEST(VisionQuantumCatch, LineAtLambdaMaxMaximisesThatCone) {
  Observer o = pigmentsOnly();
  std::vector<float> light = equalQuantumSpectrum(o.grid);
  const double lambdaMax[4] = {371.0, 448.0, 502.0, 563.0};
  for (std::size_t c = 0; c < 4; ++c) {
    // Cone c's catch of a monochromatic line is largest for the line at its lambdaMax.
    double best = 0.0, bestWl = 0.0;
    for (double wl = 300.0; wl <= 830.0; wl += 1.0) {
      double q = quantumCatches(o, line(o.grid, wl), light).chromatic[c];
      if (q > best) best = q, bestWl = wl;
    }
    EXPECT_NEAR(bestWl, lambdaMax[c], 1.0);
    // Of the lines at the four cones' lambdaMax, the one at cone c's gives cone c its largest share.
    std::vector<double> own = relativeCatches(quantumCatches(o, line(o.grid, lambdaMax[c]), light).chromatic);
    for (std::size_t other = 0; other < 4; ++other) {
      if (other == c) continue;
      std::vector<double> r = relativeCatches(quantumCatches(o, line(o.grid, lambdaMax[other]), light).chromatic);
      EXPECT_GT(own[c], r[c]) << "cone " << c << ", line at " << lambdaMax[other];
    }
  }
}

TEST(VisionQuantumCatch, MismatchedSpectraAreErrors) {
  Observer o = namedObserver("bluetit");
  EXPECT_THROW(quantumCatches(o, std::vector<float>(10, 1.0f), equalQuantumSpectrum(o.grid)), std::invalid_argument);
}

TEST(VisionColourDistance, ReceptorNoiseFromWeberFractionAndDensities) {
  // e_i = 0.1 * sqrt(4 / eta_i) for densities 1:2:2:4 and the LWS cone's Weber fraction 0.1.
  std::vector<double> e = receptorNoise({{1, 2, 2, 4}, 0.1, 3, 0.1});
  ASSERT_EQ(e.size(), 4u);
  EXPECT_NEAR(e[0], 0.2, 1e-12);
  EXPECT_NEAR(e[1], 0.1 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e[2], 0.1 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e[3], 0.1, 1e-12);
}

TEST(VisionColourDistance, IdenticalSpectraAreZeroApart) {
  Observer o = namedObserver("bluetit");
  std::vector<float> r =
      tabulateOnGrid(o.grid, [](double wl) { return 0.1 + 0.5 * std::exp(-std::pow((wl - 520.0) / 40.0, 2)); });
  std::vector<float> light = equalQuantumSpectrum(o.grid);
  ConeCatches a = adaptedQuantumCatches(o, r, light), b = adaptedQuantumCatches(o, r, light);
  EXPECT_EQ(chromaticDistance(o, a, b), 0.0);
  EXPECT_EQ(achromaticDistance(0.3, 0.3, 0.1), 0.0);
}

TEST(VisionColourDistance, HandComputedCases) {
  // Dichromat, e = (0.1, 0.1), catches (e, 1) against (1, 1): df = (1, 0), so
  // dS = |df_1 - df_2| / sqrt(e_1^2 + e_2^2) = 1 / sqrt(0.02) = 7.0710678.
  EXPECT_NEAR(chromaticDistance({std::exp(1.0), 1.0}, {1.0, 1.0}, {0.1, 0.1}), 7.0710678, 1e-6);
  // Trichromat, e = (0.1, 0.1, 0.1), only the first catch doubled: df = (ln 2, 0, 0),
  // numerator e_3^2 (ln 2)^2 + e_2^2 (ln 2)^2 = 0.02 (ln 2)^2, denominator 3 * 0.1^4 = 3e-4,
  // dS = ln 2 * sqrt(200 / 3) = 5.659523.
  EXPECT_NEAR(chromaticDistance({2.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {0.1, 0.1, 0.1}), 5.6595230, 1e-6);
  // Tetrachromat with pavo's defaults, e = (0.2, 0.1414, 0.1414, 0.1) (e^2 = 0.04, 0.02, 0.02, 0.01),
  // only the LWS catch doubled (df = (0, 0, 0, ln 2)). The pairs with the LWS cone contribute
  // (e_2 e_3)^2 + (e_1 e_3)^2 + (e_1 e_2)^2 = 0.0004 + 0.0008 + 0.0008 = 0.002 times (ln 2)^2; the
  // denominator is 0.02*0.02*0.01 + 0.04*0.02*0.01 + 0.04*0.02*0.01 + 0.04*0.02*0.02 = 3.6e-5, so
  // dS = ln 2 * sqrt(0.002 / 3.6e-5) = 0.693147 * 7.453560 = 5.166414.
  std::vector<double> e = receptorNoise({{1, 2, 2, 4}, 0.1, 3, 0.1});
  EXPECT_NEAR(chromaticDistance({1.0, 1.0, 1.0, 2.0}, {1.0, 1.0, 1.0, 1.0}, e), 5.1664140, 1e-6);
  // Symmetric, and blind to a common scale of all catches (an achromatic change) and to per-cone
  // factors applied to both (von Kries adaptation).
  std::vector<double> a = {0.3, 0.5, 0.7, 0.9}, b = {0.35, 0.45, 0.75, 0.8};
  double d = chromaticDistance(a, b, e);
  EXPECT_NEAR(chromaticDistance(b, a, e), d, 1e-12);
  EXPECT_NEAR(chromaticDistance({0.6, 1.0, 1.4, 1.8}, b, e),
              chromaticDistance({0.3, 0.5, 0.7, 0.9}, {0.175, 0.225, 0.375, 0.4}, e), 1e-9);
  EXPECT_NEAR(chromaticDistance({3 * a[0], 5 * a[1], 7 * a[2], 9 * a[3]}, {3 * b[0], 5 * b[1], 7 * b[2], 9 * b[3]}, e),
              d, 1e-9);
  // Achromatic: |ln 2 - ln 1| / 0.1 = 6.931472.
  EXPECT_NEAR(achromaticDistance(2.0, 1.0, 0.1), 6.9314718, 1e-6);
  EXPECT_THROW(chromaticDistance({0.0, 1.0}, {1.0, 1.0}, {0.1, 0.1}), std::invalid_argument);
  EXPECT_THROW(chromaticDistance({1.0}, {1.0}, {0.1}), std::invalid_argument);
}

// A dark illuminant's white catches nothing: adapting to it divided 0 by 0 (NaN catches).
TEST(QuantumCatch, AnIlluminantDarkWhereAConeSeesCannotBeAdaptedTo) {
  const Observer o = namedObserver("bluetit");
  std::vector<float> light(o.grid.count, 0.0f);
  try {
    backgroundCatches(o, light);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the background's catch in UVS is 0"), std::string::npos) << e.what();
  }
  EXPECT_THROW(adaptedQuantumCatches(o, std::vector<float>(o.grid.count, 0.5f), light), std::invalid_argument);
}
