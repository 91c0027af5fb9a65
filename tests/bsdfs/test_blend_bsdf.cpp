#include <gtest/gtest.h>

#include "bsdfs/blendbsdf.h"
#include "bsdfs/dielectric.h"
#include "bsdfs/diffuse.h"
#include "bsdfs/microfacet.h"
#include "bsdfs/roughconductor.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;

std::shared_ptr<BSDF> diffuse(float albedo) {
  return std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(albedo));
}
std::shared_ptr<BSDF> roughMirror(float alpha) {
  return std::make_shared<RoughConductorBSDF>(MicrofacetDistribution(MicrofacetType::GGX, alpha, alpha), std::nullopt,
                                              SpectralDistribution::constant(1.0f));
}
}  // namespace

TEST(BlendBSDF, IsTheLinearBlendOfItsBSDFs) {
  auto a = diffuse(0.8f), b = roughMirror(0.2f);
  BlendBSDF blend(a, b, 0.3f);
  const Wavelengths wl = testWavelengths();
  Vec3 wi = directionAt(30.0f, 10.0f);
  for (Vec3 wo : {directionAt(30.0f, 190.0f), directionAt(60.0f, 100.0f)}) {
    EXPECT_NEAR(blend.eval(kContext, wi, wo, wl)[0],
                0.7f * a->eval(kContext, wi, wo, wl)[0] + 0.3f * b->eval(kContext, wi, wo, wl)[0], 1e-6f);
    EXPECT_NEAR(blend.pdf(kContext, wi, wo, wl),
                0.7f * a->pdf(kContext, wi, wo, wl) + 0.3f * b->pdf(kContext, wi, wo, wl), 1e-5f);
  }
}

TEST(BlendBSDF, SamplingMatchesPdfAndWeightsAreEvalOverPdf) {
  BlendBSDF blend(diffuse(0.8f), roughMirror(0.2f), 0.3f);
  const float angles[] = {0.0f, 45.0f, 80.0f};
  for (float theta : angles) {
    Vec3 wi = directionAt(theta, 30.0f);
    ChiSquareResult chi = chiSquareBSDF(blend, wi, chiSquareGrid(0.2f));
    EXPECT_GT(chi.pValue, sidakThreshold(0.01, 3)) << "theta " << theta << ": " << chi.message;
    EXPECT_LT(maxWeightError(blend, wi), 1e-3) << "theta " << theta;
  }
  // Albedo: 0.7 x 0.8 from the diffuse part plus 0.3 x the rough mirror's, by two estimators.
  Vec3 wi = directionAt(20.0f);
  float mirror = sampledAlbedo(*roughMirror(0.2f), wi, 100000)[0];
  EXPECT_NEAR(sampledAlbedo(blend, wi, 200000)[0], 0.7f * 0.8f + 0.3f * mirror, 0.005f);
}

TEST(BlendBSDF, DeltaComponentsKeepTheirWeight) {
  auto glass = std::make_shared<DielectricBSDF>(1.5f, SpectralDistribution::constant(1.0f),
                                                SpectralDistribution::constant(1.0f));
  BlendBSDF blend(diffuse(0.5f), glass, 0.25f);
  EXPECT_FALSE(blend.isDeltaOnly());
  Vec3 wi = directionAt(0.0f);
  auto s = blend.sample(kContext, wi, testWavelengths(), 0.9f, Vec2(0.5f, 0.5f));  // the glass, refracting
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->delta);
  EXPECT_NEAR(s->pdf, 0.25f * (1.0f - 0.04f), 1e-5f);
  // The blend's mean weight is 0.75 x 0.5 for the diffuse part plus 0.25 x the glass's: r = 0.04
  // reflected and (1 - r) / eta^2 refracted (radiance entering the denser side is compressed).
  EXPECT_NEAR(sampledAlbedo(blend, wi, 100000)[0], 0.75f * 0.5f + 0.25f * (0.04f + 0.96f / 2.25f), 0.005f);
}

TEST(BlendBSDF, FactoryNeedsTwoBSDFsAndAWeightInRange) {
  Properties props;
  setFloat(props, "weight", 0.2f);
  addNested(props, diffuse(0.5f));
  EXPECT_THROW(makeBlendBSDF(props), InputError);
  addNested(props, diffuse(0.1f));
  auto bsdf = std::dynamic_pointer_cast<BSDF>(makeBlendBSDF(props));
  ASSERT_TRUE(bsdf);
  EXPECT_NEAR(bsdf->eval(kContext, directionAt(0.0f), directionAt(0.0f), testWavelengths())[0],
              (0.8f * 0.5f + 0.2f * 0.1f) * kInvPi, 1e-6f);
  Properties negative;
  setFloat(negative, "weight", -0.1f);
  addNested(negative, diffuse(0.5f));
  addNested(negative, diffuse(0.1f));
  EXPECT_THROW(makeBlendBSDF(negative), InputError);
}
