// BSDF::samplesAllItScatters: a BSDF that claims it can draw every direction where it has a value
// (pdf > 0 there), on which emitter sampling then relies to leave a constant environment to the
// BSDF samples (Scene::EmitterSet).
#include <gtest/gtest.h>

#include "core/rng.h"
#include "core/sampling.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
// Outgoing directions, uniform over the sphere, where the BSDF has a value but no density.
int uncoveredDirections(const BSDF& bsdf, const Vec3& wi, int count) {
  const BSDFContext ctx;
  const Wavelengths wl = testWavelengths();
  PCG32 rng(5, 3);
  int uncovered = 0;
  for (int n = 0; n < count; ++n) {
    const Vec3 wo = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    if (bsdf.eval(ctx, wi, wo, wl).maxValue() > 0.0f && !(bsdf.pdf(ctx, wi, wo, wl) > 0.0f)) ++uncovered;
  }
  return uncovered;
}
}  // namespace

TEST(BSDFSamplingCoverage, EveryBSDFThatClaimsItDrawsWhereverItHasAValue) {
  const std::vector<std::pair<std::string, std::string>> bsdfs = {
      {"diffuse", ""},
      {"roughconductor", R"(<float name="alpha" value="0.3"/>)"},
      {"roughplastic", R"(<float name="alpha" value="0.2"/>)"},
      {"plastic", ""},
      {"roughdielectric", R"(<float name="alpha" value="0.3"/>)"},
      {"principled", R"(<float name="roughness" value="0.4"/> <float name="clearcoat" value="0.5"/>)"},
      {"principledthin", R"(<float name="roughness" value="0.4"/> <float name="diff_trans" value="0.3"/>
                            <float name="spec_trans" value="0.4"/>)"},
      {"twosided", R"(<bsdf type="roughconductor"><float name="alpha" value="0.2"/></bsdf>)"},
      {"blendbsdf", R"(<float name="weight" value="0.3"/> <bsdf type="diffuse"/>
                       <bsdf type="roughconductor"><float name="alpha" value="0.1"/></bsdf>)"},
      {"barbulebsdf", ""},
      {"barbulebsdf",
       R"(<float name="b" value="0.4"/> <float name="phi_0" value="0.2"/> <float name="H" value="1.6"/>)"},
  };
  for (const auto& [type, parameters] : bsdfs) {
    std::shared_ptr<BSDF> bsdf = loadBSDF(type, parameters);
    ASSERT_TRUE(bsdf) << type;
    EXPECT_TRUE(bsdf->samplesAllItScatters()) << type;
    for (float theta : {5.0f, 40.0f, 75.0f, 120.0f})
      for (float phi : {0.0f, 70.0f})
        EXPECT_EQ(uncoveredDirections(*bsdf, directionAt(theta, phi), 20000), 0)
            << type << " " << parameters << ", wi at theta " << theta << ", phi " << phi;
  }
}

// A strategy switched off leaves directions with a value but no density: such a BSDF must not
// claim coverage.
TEST(BSDFSamplingCoverage, APrincipledBSDFWithAStrategyOffDoesNotClaimIt) {
  // Light through a rough transmitting principled BSDF is drawn by its specular strategy only.
  std::shared_ptr<BSDF> bsdf = loadBSDF("principled", R"(<float name="roughness" value="0.4"/>
      <float name="spec_trans" value="0.6"/> <float name="main_specular_sampling_rate" value="0"/>)");
  EXPECT_FALSE(bsdf->samplesAllItScatters());
  EXPECT_GT(uncoveredDirections(*bsdf, directionAt(30.0f), 20000), 0);
  EXPECT_FALSE(loadBSDF("twosided", R"(<bsdf type="principled">
      <float name="main_specular_sampling_rate" value="0"/></bsdf>)")
                   ->samplesAllItScatters());
}
