#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/roughdielectric.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;
const MicrofacetType kTypes[] = {MicrofacetType::Beckmann, MicrofacetType::GGX};
const char* name(MicrofacetType t) { return t == MicrofacetType::GGX ? "ggx" : "beckmann"; }

RoughDielectricBSDF glass(MicrofacetType type, float alpha, float eta = 1.5f) {
  return RoughDielectricBSDF(MicrofacetDistribution(type, alpha, alpha), eta, SpectralDistribution::constant(1.0f),
                             SpectralDistribution::constant(1.0f));
}

// wi from outside (theta < 90) and from inside the glass (theta > 90).
const float kAngles[] = {0.0f, 40.0f, 80.0f, 140.0f, 175.0f};
}  // namespace

TEST(RoughDielectric, SamplingMatchesPdfOnBothSidesSlow) {
  const int tests = 2 * 2 * int(std::size(kAngles));
  const double threshold = sidakThreshold(0.01, tests);
  uint64_t seed = 1;
  for (MicrofacetType type : kTypes)
    for (float alpha : {0.15f, 0.5f}) {
      RoughDielectricBSDF bsdf = glass(type, alpha);
      // Refraction narrows the lobe (by about (eta - 1) / eta near normal incidence): finer bins and
      // more quadrature nodes than a reflection lobe of the same roughness needs.
      ChiSquareGrid grid = alpha < 0.2f ? ChiSquareGrid{80, 40, 64} : chiSquareGrid(0.4f * alpha);
      for (float theta : kAngles) {
        ChiSquareResult r = chiSquareBSDF(bsdf, directionAt(theta, 25.0f), grid, 300000, seed++);
        std::cout << name(type) << " alpha " << alpha << " theta " << theta << ": " << r.message << "\n";
        EXPECT_GT(r.pValue, threshold) << name(type) << " alpha " << alpha << " theta " << theta << ": " << r.message;
      }
    }
}

TEST(RoughDielectric, WeightIsEvalOverPdf) {
  for (MicrofacetType type : kTypes)
    for (float theta : kAngles)
      EXPECT_LT(maxWeightError(glass(type, 0.3f), directionAt(theta, 60.0f)), 2e-3) << name(type) << " " << theta;
}

TEST(RoughDielectric, NearlySmoothGlassSplitsAsFresnelSays) {
  // Almost smooth (alpha 0.01), at normal incidence from outside: r = ((1.5 - 1) / (1.5 + 1))^2 =
  // 0.04 reflected, the rest refracted with radiance scaled by 1 / 1.5^2. From inside, the same r
  // and the refracted radiance scaled by 1.5^2.
  RoughDielectricBSDF bsdf = glass(MicrofacetType::GGX, 0.01f);
  const Wavelengths wl = testWavelengths();
  for (bool inside : {false, true}) {
    Vec3 wi(0.0f, 0.0f, inside ? -1.0f : 1.0f);
    double reflected = 0.0, refracted = 0.0;
    PCG32 rng(5, 9);
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
      auto s = bsdf.sample(kContext, wi, wl, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
      if (!s) continue;
      (sameHemisphere(s->wo, wi) ? reflected : refracted) += s->weight[0] / n;
    }
    float scale = inside ? 2.25f : 1.0f / 2.25f;
    EXPECT_NEAR(reflected, 0.04, 0.002) << (inside ? "inside" : "outside");
    EXPECT_NEAR(refracted, 0.96 * scale, 0.01 * scale) << (inside ? "inside" : "outside");
  }
}

TEST(RoughDielectric, RefractionFollowsSnellOnAverage) {
  // A narrow lobe from 45 degrees outside refracts around asin(sin 45 / 1.5) = 28.13 degrees.
  RoughDielectricBSDF bsdf = glass(MicrofacetType::Beckmann, 0.02f);
  Vec3 wi = directionAt(45.0f, 0.0f);
  PCG32 rng(2, 3);
  double sumSin = 0.0;
  int count = 0;
  for (int i = 0; i < 20000; ++i) {
    auto s = bsdf.sample(kContext, wi, testWavelengths(), 0.999f, Vec2(rng.nextFloat(), rng.nextFloat()));
    if (!s || s->wo.z >= 0.0f) continue;
    sumSin += -s->wo.x;  // the refracted ray leaves on the other side of the normal's plane
    ++count;
  }
  ASSERT_GT(count, 19000);
  EXPECT_NEAR(sumSin / count, std::sin(degToRad(45.0f)) / 1.5f, 2e-3);
}

TEST(RoughDielectric, FactoryReadsMitsubasParameters) {
  Properties props;
  setString(props, "distribution", "ggx");
  setFloat(props, "alpha", 0.2f);
  setFloat(props, "int_ior", 1.33f);
  setFloat(props, "ext_ior", 1.0f);
  auto bsdf = std::dynamic_pointer_cast<BSDF>(makeRoughDielectricBSDF(props));
  ASSERT_TRUE(bsdf);
  RoughDielectricBSDF direct = glass(MicrofacetType::GGX, 0.2f, 1.33f);
  Vec3 wi = directionAt(30.0f), wo = directionAt(160.0f, 180.0f);
  EXPECT_FLOAT_EQ(bsdf->eval(kContext, wi, wo, testWavelengths())[0],
                  direct.eval(kContext, wi, wo, testWavelengths())[0]);
  EXPECT_GT(direct.eval(kContext, wi, wo, testWavelengths())[0], 0.0f);
}
