#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/diffuse.h"
#include "bsdfs/roughconductor.h"
#include "bsdfs/twosided.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

std::shared_ptr<BSDF> diffuse(float reflectance) {
  return std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(reflectance));
}

Vec3 below(const Vec3& w) { return Vec3(w.x, w.y, -w.z); }

}  // namespace

TEST(TwoSided, OneNestedBSDFServesBothSides) {
  TwoSidedBSDF bsdf(diffuse(0.3f), diffuse(0.3f));
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(30.0f, 10.0f), wo = directionAt(50.0f, 200.0f);
  float front = bsdf.eval({}, wi, wo, wl)[0];
  EXPECT_NEAR(front, 0.3f * kInvPi * wo.z, 1e-6f);
  EXPECT_NEAR(bsdf.eval({}, below(wi), below(wo), wl)[0], front, 1e-6f);
  EXPECT_NEAR(bsdf.pdf({}, below(wi), below(wo), wl), wo.z * kInvPi, 1e-6f);
}

TEST(TwoSided, BackBSDFScattersBelowTheSurface) {
  TwoSidedBSDF bsdf(diffuse(0.2f), diffuse(0.8f));
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(40.0f), wo = directionAt(20.0f, 90.0f);
  EXPECT_NEAR(bsdf.eval({}, wi, wo, wl)[0], 0.2f * kInvPi * wo.z, 1e-6f);
  EXPECT_NEAR(bsdf.eval({}, below(wi), below(wo), wl)[0], 0.8f * kInvPi * wo.z, 1e-6f);
  // Nothing crosses from one side to the other.
  EXPECT_TRUE(bsdf.eval({}, wi, below(wo), wl).isZero());
  EXPECT_TRUE(bsdf.eval({}, below(wi), wo, wl).isZero());
  EXPECT_EQ(bsdf.pdf({}, below(wi), wo, wl), 0.0f);

  PCG32 rng(2, 2);
  for (int i = 0; i < 100; ++i) {
    auto s = bsdf.sample({}, below(wi), wl, rng.nextFloat(), Vec2(rng.nextFloat(), rng.nextFloat()));
    ASSERT_TRUE(s);
    EXPECT_LT(s->wo.z, 0.0f);
    EXPECT_NEAR(s->weight[0], 0.8f, 1e-6f);
  }
}

TEST(TwoSided, SamplingMatchesPdfFromBelow) {
  auto metal = std::make_shared<RoughConductorBSDF>(MicrofacetDistribution(MicrofacetType::GGX, 0.3f, 0.3f),
                                                    std::nullopt, SpectralDistribution::constant(1.0f));
  TwoSidedBSDF bsdf(diffuse(0.5f), metal);
  const double threshold = sidakThreshold(0.01, 2);
  uint64_t seed = 1;
  for (float theta : {30.0f, 70.0f}) {
    auto result = chiSquareBSDF(bsdf, below(directionAt(theta, 60.0f)), chiSquareGrid(0.3f), 200000, seed++);
    std::cout << "twosided back roughconductor theta " << theta << ": " << result.message << "\n";
    EXPECT_GT(result.pValue, threshold) << "theta " << theta;
  }
}

TEST(TwoSided, FactoryTakesOneOrTwoNestedBSDFs) {
  const Wavelengths wl = testWavelengths();
  Vec3 wi = below(directionAt(0.0f)), wo = below(directionAt(0.0f));

  Properties one;
  addNested(one, diffuse(0.4f));
  auto shared = std::dynamic_pointer_cast<BSDF>(makeTwoSidedBSDF(one));
  ASSERT_TRUE(shared);
  EXPECT_NO_THROW(one.checkAllUsed());
  EXPECT_NEAR(shared->eval({}, wi, wo, wl)[0], 0.4f * kInvPi, 1e-6f);

  Properties two;
  addNested(two, diffuse(0.4f));
  addNested(two, diffuse(0.6f));
  auto separate = std::dynamic_pointer_cast<BSDF>(makeTwoSidedBSDF(two));
  EXPECT_NEAR(separate->eval({}, wi, wo, wl)[0], 0.6f * kInvPi, 1e-6f);

  Properties none;
  EXPECT_THROW(makeTwoSidedBSDF(none), InputError);
  Properties three;
  for (int i = 0; i < 3; ++i) addNested(three, diffuse(0.5f));
  EXPECT_THROW(makeTwoSidedBSDF(three), InputError);
}
