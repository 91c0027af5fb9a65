// The BSDFs that let light through untouched in part or whole: null, mask, thindielectric.
#include <gtest/gtest.h>

#include "bsdfs/diffuse.h"
#include "bsdfs/mask.h"
#include "bsdfs/null.h"
#include "bsdfs/thindielectric.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;

std::shared_ptr<BSDF> fromPlugin(std::shared_ptr<Object> object) { return std::dynamic_pointer_cast<BSDF>(object); }
}  // namespace

TEST(NullBSDF, PassesEverythingAndScattersNothing) {
  NullBSDF bsdf;
  Vec3 wi = directionAt(40.0f, 70.0f);
  auto s = bsdf.sample(kContext, wi, testWavelengths(), 0.3f, Vec2(0.2f, 0.9f));
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->passThrough && s->delta);
  EXPECT_EQ(s->wo.z, -wi.z);
  EXPECT_EQ(s->weight[0], 1.0f);
  EXPECT_EQ(bsdf.passThrough(kContext, wi, testWavelengths())[2], 1.0f);
  EXPECT_TRUE(bsdf.eval(kContext, wi, directionAt(10.0f), testWavelengths()).isZero());
  EXPECT_TRUE(fromPlugin(makeNullBSDF(Properties())));
}

TEST(MaskBSDF, ScalesTheNestedBSDFByTheOpacityAndPassesTheRest) {
  auto diffuse = std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(0.5f));
  MaskBSDF mask(diffuse, 0.3f);
  const Wavelengths wl = testWavelengths();
  for (float theta : {0.0f, 50.0f}) {
    Vec3 wi = directionAt(theta, 20.0f), wo = directionAt(35.0f, 200.0f);
    EXPECT_NEAR(mask.eval(kContext, wi, wo, wl)[1], 0.3f * diffuse->eval(kContext, wi, wo, wl)[1], 1e-7f);
    EXPECT_NEAR(mask.pdf(kContext, wi, wo, wl), 0.3f * diffuse->pdf(kContext, wi, wo, wl), 1e-7f);
    EXPECT_NEAR(mask.passThrough(kContext, wi, wl)[0], 0.7f, 1e-7f);
    // Everything that arrives leaves: 0.7 straight through, 0.3 x 0.5 reflected.
    EXPECT_NEAR(sampledAlbedo(mask, wi, 200000)[0], 0.7f + 0.3f * 0.5f, 0.003f);
    EXPECT_LT(maxWeightError(mask, wi), 1e-4);
    ChiSquareResult chi = chiSquareBSDF(mask, wi);
    EXPECT_GT(chi.pValue, sidakThreshold(0.01, 2)) << chi.message;
  }
  // A caller that carries the pass-through itself gets the nested BSDF's samples, with its
  // density and the opacity in the weight.
  BSDFContext byCaller;
  byCaller.passThroughByCaller = true;
  Vec3 wi = directionAt(30.0f, 10.0f);
  for (float uComponent : {0.05f, 0.5f, 0.95f}) {
    auto s = mask.sample(byCaller, wi, wl, uComponent, Vec2(0.3f, 0.6f));
    auto nested = diffuse->sample(byCaller, wi, wl, uComponent, Vec2(0.3f, 0.6f));
    ASSERT_TRUE(s && nested);
    EXPECT_FALSE(s->passThrough);
    EXPECT_EQ(s->wo, nested->wo);
    EXPECT_NEAR(s->pdf, nested->pdf, 1e-7f);
    EXPECT_NEAR(mask.pdf(byCaller, wi, s->wo, wl), nested->pdf, 1e-6f);
    EXPECT_NEAR(s->weight[0], 0.3f * nested->weight[0], 1e-6f);
  }
  // A mask of a BSDF that passes light itself lets that part through too.
  MaskBSDF maskOfNull(std::make_shared<NullBSDF>(), 0.4f);
  EXPECT_NEAR(maskOfNull.passThrough(kContext, directionAt(10.0f), wl)[0], 1.0f, 1e-7f);
}

TEST(MaskBSDF, FactoryReadsOpacityAndOneNestedBSDF) {
  Properties props;
  setFloat(props, "opacity", 0.25f);
  addNested(props, std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(0.5f)));
  auto bsdf = fromPlugin(makeMaskBSDF(props));
  ASSERT_TRUE(bsdf);
  EXPECT_NEAR(bsdf->passThrough(kContext, directionAt(0.0f), testWavelengths())[0], 0.75f, 1e-7f);
  Properties none;
  EXPECT_THROW(makeMaskBSDF(none), InputError);
  Properties opaque;
  setFloat(opaque, "opacity", 1.5f);
  addNested(opaque, std::make_shared<NullBSDF>());
  EXPECT_THROW(makeMaskBSDF(opaque), InputError);
}

TEST(ThinDielectricBSDF, ReflectsTheSheetsReflectanceAndPassesTheRest) {
  // Glass of index 1.5 at normal incidence: r = (0.5 / 2.5)^2 = 0.04 per face; with the light
  // bouncing between the faces, R = 2 r / (1 + r) = 0.08 / 1.04.
  ThinDielectricBSDF sheet(1.5f, SpectralDistribution::constant(1.0f), SpectralDistribution::constant(1.0f));
  const float R = 0.08f / 1.04f;
  EXPECT_NEAR(sheet.sheetReflectance(1.0f), R, 1e-6f);
  EXPECT_NEAR(sheet.sheetReflectance(-1.0f), R, 1e-6f);  // the same from the other side
  const Wavelengths wl = testWavelengths();
  for (Vec3 wi : {directionAt(0.0f), Vec3(0.0f, 0.0f, -1.0f)}) {
    EXPECT_NEAR(sheet.passThrough(kContext, wi, wl)[0], 1.0f - R, 1e-6f);
    auto reflected = sheet.sample(kContext, wi, wl, 0.5f * R, Vec2(0.5f, 0.5f));
    ASSERT_TRUE(reflected);
    EXPECT_FALSE(reflected->passThrough);
    EXPECT_NEAR(reflected->wo.z, wi.z, 1e-7f);
    EXPECT_NEAR(reflected->pdf, R, 1e-6f);
    auto through = sheet.sample(kContext, wi, wl, 0.5f + 0.5f * R, Vec2(0.5f, 0.5f));
    ASSERT_TRUE(through);
    EXPECT_TRUE(through->passThrough && through->delta);
    EXPECT_NEAR(through->wo.z, -wi.z, 1e-7f);
  }
  // Energy is conserved at every angle: R + T = 1 over many samples, and R grows toward grazing.
  EXPECT_NEAR(sampledAlbedo(sheet, directionAt(70.0f), 10000)[0], 1.0f, 1e-5f);
  EXPECT_GT(sheet.sheetReflectance(std::cos(degToRad(80.0f))), 0.5f);

  Properties props;
  setFloat(props, "int_ior", 1.5f);
  setFloat(props, "ext_ior", 1.0f);
  auto fromScene = fromPlugin(makeThinDielectricBSDF(props));
  ASSERT_TRUE(fromScene);
  EXPECT_NEAR(fromScene->passThrough(kContext, directionAt(0.0f), wl)[0], 1.0f - R, 1e-6f);
}
