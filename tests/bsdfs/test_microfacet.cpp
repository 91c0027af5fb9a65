#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/microfacet.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

struct Roughness {
  float x, y;
};
const Roughness kRoughness[] = {{0.1f, 0.1f}, {0.4f, 0.4f}, {0.9f, 0.9f}, {0.15f, 0.6f}};
const MicrofacetType kTypes[] = {MicrofacetType::Beckmann, MicrofacetType::GGX};
const char* name(MicrofacetType t) { return t == MicrofacetType::GGX ? "ggx" : "beckmann"; }

// Midpoint rule over the upper hemisphere in (theta, phi), fine enough for alpha >= 0.1.
template <typename F>
double integrateHemisphere(F f) {
  constexpr int kTheta = 2000, kPhi = 128;
  const double dTheta = 0.5 * M_PI / kTheta, dPhi = 2.0 * M_PI / kPhi;
  double sum = 0.0;
  for (int i = 0; i < kTheta; ++i) {
    double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < kPhi; ++j) {
      double phi = (j + 0.5) * dPhi;
      Vec3 m(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
      sum += f(m) * std::sin(theta);
    }
  }
  return sum * dTheta * dPhi;
}

}  // namespace

TEST(Microfacet, ProjectedAreaIsOne) {
  for (MicrofacetType type : kTypes)
    for (Roughness r : kRoughness) {
      MicrofacetDistribution d(type, r.x, r.y);
      double area = integrateHemisphere([&](const Vec3& m) { return double(d.D(m)) * m.z; });
      EXPECT_NEAR(area, 1.0, 2e-3) << name(type) << " alpha " << r.x << "," << r.y;
    }
}

TEST(Microfacet, VisibleNormalDensityIntegratesToOneSlow) {
  // Holds only if Lambda is consistent with D: the visible projected area of the microfacets
  // is wi.z (1 + Lambda(wi)).
  for (MicrofacetType type : kTypes)
    for (Roughness r : kRoughness)
      for (float theta : {0.0f, 45.0f, 80.0f}) {
        MicrofacetDistribution d(type, r.x, r.y);
        Vec3 wi = directionAt(theta, 30.0f);
        double total = integrateHemisphere([&](const Vec3& m) { return double(d.visiblePdf(wi, m)); });
        EXPECT_NEAR(total, 1.0, 3e-3) << name(type) << " alpha " << r.x << "," << r.y << " theta " << theta;
      }
}

TEST(Microfacet, MaskingIsAFractionAndZeroForBackfacingNormals) {
  MicrofacetDistribution d(MicrofacetType::GGX, 0.3f, 0.3f);
  Vec3 m = normalize(Vec3(0.3f, 0.0f, 1.0f));
  for (float theta : {0.0f, 30.0f, 60.0f, 89.0f}) {
    float g = d.G1(directionAt(theta), m);
    EXPECT_GT(g, 0.0f);
    EXPECT_LE(g, 1.0f);
  }
  EXPECT_GT(d.G1(directionAt(10.0f), m), d.G1(directionAt(80.0f, 180.0f), m));
  EXPECT_EQ(d.G1(directionAt(88.0f, 180.0f), m), 0.0f);  // sees the facet from behind
  EXPECT_EQ(d.G1(Vec3(0.995f, 0.0f, -0.1f), m), 0.0f);   // from below, facing the facet's front
}

TEST(Microfacet, VisibleNormalSamplingMatchesPdfSlow) {
  const float angles[] = {0.0f, 30.0f, 60.0f, 85.0f};
  const int tests = 2 * 4 * 4;
  const double threshold = sidakThreshold(0.01, tests);
  double minP = 1.0;
  uint64_t seed = 1;
  for (MicrofacetType type : kTypes)
    for (Roughness r : kRoughness)
      for (float theta : angles) {
        MicrofacetDistribution d(type, r.x, r.y);
        Vec3 wi = directionAt(theta, 30.0f);
        ChiSquareGrid grid = chiSquareGrid(std::min(r.x, r.y));
        auto result = chiSquareDirectionTest(
            [&](PCG32& rng) -> std::optional<Vec3> {
              float u1 = rng.nextFloat();
              return d.sampleVisible(wi, Vec2(u1, rng.nextFloat()));
            },
            [&](const Vec3& m) { return double(d.visiblePdf(wi, m)); }, 100000, grid.thetaBins, grid.phiBins,
            grid.quadrature, seed++);
        std::cout << name(type) << " alpha " << r.x << "," << r.y << " theta " << theta << ": " << result.message
                  << "\n";
        EXPECT_GT(result.pValue, threshold) << name(type) << " alpha " << r.x << "," << r.y << " theta " << theta;
        minP = std::min(minP, result.pValue);
      }
  std::cout << "visible normals: min p = " << minP << " (threshold " << threshold << ")\n";
}
