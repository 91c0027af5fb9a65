#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/diffuse.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const float kAngles[] = {0.0f, 30.0f, 60.0f, 85.0f};
}

TEST(Diffuse, SamplingMatchesPdf) {
  DiffuseBSDF bsdf(SpectralDistribution::constant(0.5f));
  const double threshold = sidakThreshold(0.01, 4);
  uint64_t seed = 1;
  for (float theta : kAngles) {
    auto result = chiSquareBSDF(bsdf, directionAt(theta, 20.0f), {}, 200000, seed++);
    std::cout << "diffuse theta=" << theta << ": " << result.message << "\n";
    EXPECT_GT(result.pValue, threshold) << "theta " << theta;
  }
}

TEST(Diffuse, WeightIsEvalOverPdf) {
  DiffuseBSDF bsdf(SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.2f, 0.9f}));
  for (float theta : kAngles) EXPECT_LT(maxWeightError(bsdf, directionAt(theta)), 1e-4) << "theta " << theta;
}

TEST(Diffuse, AlbedoEqualsReflectance) {
  SpectralDistribution reflectance = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.2f, 0.9f});
  DiffuseBSDF bsdf(reflectance);
  Spectrum expected = reflectance.sample(testWavelengths());
  for (float theta : {0.0f, 60.0f}) {
    Spectrum integrated = integratedAlbedo(bsdf, directionAt(theta), 100000);
    Spectrum sampled = sampledAlbedo(bsdf, directionAt(theta), 1000);
    for (int i = 0; i < kSpectrumSamples; ++i) {
      EXPECT_NEAR(integrated[i], expected[i], 0.01f) << "theta " << theta;
      EXPECT_NEAR(sampled[i], expected[i], 1e-5f) << "theta " << theta;
    }
  }
}

TEST(Diffuse, IsReciprocal) {
  DiffuseBSDF bsdf(SpectralDistribution::constant(0.7f));
  const Wavelengths wl = testWavelengths();
  Vec3 a = directionAt(20.0f, 10.0f), b = directionAt(70.0f, 200.0f);
  float fab = bsdf.eval({}, a, b, wl)[0] / b.z, fba = bsdf.eval({}, b, a, wl)[0] / a.z;
  EXPECT_NEAR(fab, 0.7f * kInvPi, 1e-6f);
  EXPECT_NEAR(fab, fba, 1e-6f);
}

TEST(Diffuse, IsBlackFromBelowAndInTransmission) {
  DiffuseBSDF bsdf(SpectralDistribution::constant(0.5f));
  const Wavelengths wl = testWavelengths();
  Vec3 up = directionAt(30.0f), down = -directionAt(40.0f);
  EXPECT_TRUE(bsdf.eval({}, up, down, wl).isZero());
  EXPECT_TRUE(bsdf.eval({}, down, up, wl).isZero());
  EXPECT_EQ(bsdf.pdf({}, down, up, wl), 0.0f);
  EXPECT_FALSE(bsdf.sample({}, down, wl, 0.5f, Vec2(0.3f, 0.6f)));
}

TEST(Diffuse, FactoryReadsReflectance) {
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(0.0f), wo = directionAt(0.0f);
  Properties defaults;
  auto plain = std::dynamic_pointer_cast<BSDF>(makeDiffuseBSDF(defaults));
  ASSERT_TRUE(plain);
  EXPECT_NEAR(plain->eval({}, wi, wo, wl)[0], 0.5f * kInvPi, 1e-6f);
  Properties props;
  setFloat(props, "reflectance", 0.25f);
  auto grey = std::dynamic_pointer_cast<BSDF>(makeDiffuseBSDF(props));
  EXPECT_NEAR(grey->eval({}, wi, wo, wl)[2], 0.25f * kInvPi, 1e-6f);
  EXPECT_NO_THROW(props.checkAllUsed());
}
