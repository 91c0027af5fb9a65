// Mitsuba 3's `principledthin` BSDF: sampling against the density, weights, energy, symmetry
// between the sheet's sides, reciprocity, its Lambertian limit, and reading it from a scene.
#include <gtest/gtest.h>

#include <iostream>
#include "bsdfs/principledthin.h"
#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "support/bsdf_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
const BSDFContext kContext;

struct NamedParameters {
  const char* name;
  PrincipledThinParameters parameters;
};

// Every lobe: the diffuse default, a glossy translucent sheet, a sheet that mostly transmits
// diffusely, an anisotropic one with sheen and flatness.
std::vector<NamedParameters> parameterSets() {
  std::vector<NamedParameters> sets;
  sets.push_back({"default", PrincipledThinParameters{}});
  PrincipledThinParameters glossy;
  glossy.specTrans = 0.8f;
  glossy.roughness = 0.4f;
  glossy.eta = 1.33f;
  glossy.specTint = 0.3f;
  sets.push_back({"glossy", glossy});
  PrincipledThinParameters translucent;
  translucent.diffTrans = 1.5f;
  translucent.specTrans = 0.3f;
  translucent.roughness = 0.6f;
  sets.push_back({"translucent", translucent});
  PrincipledThinParameters cloth;
  cloth.specTrans = 0.5f;
  cloth.diffTrans = 0.6f;
  cloth.anisotropic = 0.7f;
  cloth.roughness = 0.5f;
  cloth.sheen = 1.0f;
  cloth.sheenTint = 0.5f;
  cloth.flatness = 0.6f;
  sets.push_back({"cloth", cloth});
  return sets;
}

const float kAngles[] = {10.0f, 50.0f, 80.0f, 140.0f};

std::shared_ptr<BSDF> loadThin(const std::string& parameters) { return loadBSDF("principledthin", parameters); }
std::string loadError(const std::string& parameters) { return loadBSDFError("principledthin", parameters); }
}  // namespace

TEST(PrincipledThin, SamplingMatchesPdfSlow) {
  const double threshold = sidakThreshold(0.01, int(parameterSets().size() * std::size(kAngles)));
  double minP = 1.0;
  uint64_t seed = 1;
  for (const auto& set : parameterSets()) {
    PrincipledThinBSDF bsdf(set.parameters);
    for (float theta : kAngles) {
      ChiSquareResult r = chiSquareBSDF(bsdf, directionAt(theta, 35.0f), chiSquareGrid(0.1f), 300000, seed++);
      std::cout << set.name << " theta " << theta << ": " << r.message << "\n";
      EXPECT_GT(r.pValue, threshold) << set.name << " theta " << theta << ": " << r.message;
      minP = std::min(minP, r.pValue);
    }
  }
  std::cout << "principledthin: min p = " << minP << " (threshold " << threshold << ")\n";
}

TEST(PrincipledThin, WeightIsEvalOverPdf) {
  for (auto set : parameterSets()) {
    set.parameters.baseColor = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.2f, 0.9f});
    PrincipledThinBSDF bsdf(set.parameters);
    for (float theta : kAngles)
      EXPECT_LT(maxWeightError(bsdf, directionAt(theta, 60.0f)), 2e-3) << set.name << " theta " << theta;
  }
}

TEST(PrincipledThin, AlbedoIsAtMostOne) {
  // A sheet does not bend light, so nothing is compressed: reflected plus transmitted at most 1.
  // Diffuse reflection is left out (Disney's diffuse lobe is not energy-conserving).
  PrincipledThinParameters glossy;
  glossy.baseColor = SpectralDistribution::constant(1.0f);
  glossy.specTrans = 1.0f;
  glossy.roughness = 0.3f;
  PrincipledThinParameters translucent = glossy;
  translucent.specTrans = 0.4f;
  translucent.diffTrans = 2.0f;
  for (const auto& p : {glossy, translucent}) {
    PrincipledThinBSDF bsdf(p);
    for (float theta : {0.0f, 45.0f, 80.0f, 150.0f}) {
      float albedo = sampledAlbedo(bsdf, directionAt(theta, 20.0f), 100000)[0];
      std::cout << "spec_trans " << p.specTrans.mean() << " theta " << theta << ": albedo " << albedo << "\n";
      EXPECT_LE(albedo, 1.01f) << "spec_trans " << p.specTrans.mean() << " theta " << theta;
      EXPECT_GT(albedo, 0.5f) << "spec_trans " << p.specTrans.mean() << " theta " << theta;
    }
  }
}

TEST(PrincipledThin, FullDiffuseTransmissionIsLambertian) {
  // diff_trans 2 with no specular part: base / pi through the sheet, nothing reflected.
  PrincipledThinParameters p;
  p.diffTrans = 2.0f;
  p.baseColor = SpectralDistribution::constant(0.7f);
  PrincipledThinBSDF bsdf(p);
  const Wavelengths wl = testWavelengths();
  const Vec3 wi = directionAt(30.0f), through = directionAt(120.0f, 200.0f), back = directionAt(50.0f, 10.0f);
  EXPECT_NEAR(bsdf.eval(kContext, wi, through, wl)[0], 0.7f * kInvPi * std::abs(through.z), 1e-6f);
  EXPECT_EQ(bsdf.eval(kContext, wi, back, wl)[0], 0.0f);
  EXPECT_NEAR(sampledAlbedo(bsdf, wi, 1000)[0], 0.7f, 1e-4f);
}

TEST(PrincipledThin, AgreesWithMitsubasReferenceValues) {
  // Mitsuba 3's own regression values (src/bsdfs/tests/test_principledthin.py,
  // test03_eval_pdf_thin), toward wo at theta = i / 19 * 90 degrees in the plane of the
  // unnormalised wi = (1, 0, 1). Mitsuba's Fresnel term takes that pair's cos(theta) above 1 as
  // given where Columba's clamps it: the source of up to 0.8 % in eval; imitating it, the values
  // agree to 2e-7. The density has no Fresnel term and agrees as it is.
  const double pdfs[] = {0.18230389, 0.17071931, 0.16046360, 0.15113641, 0.14242139, 0.13407253, 0.12590222,
                         0.11777049, 0.10957616, 0.10124958, 0.09274674, 0.08404446, 0.07513650, 0.06603056,
                         0.05674567, 0.04731012, 0.03775979, 0.02813668, 0.01848774, 0.00886382};
  const double values[] = {0.04944334, 0.04872140, 0.04784624, 0.04680282, 0.04557877, 0.04416417, 0.04255125,
                           0.04073422, 0.03870923, 0.03647450, 0.03403011, 0.03137692, 0.02851360, 0.02543111,
                           0.02210502, 0.01848825, 0.01451063, 0.01009628, 0.00521620, 3.89942e-18};
  PrincipledThinParameters p;  // base_color and roughness at their defaults
  p.eta = 1.5f;
  p.anisotropic = 0.5f;
  p.sheen = 0.5f;
  p.sheenTint = 0.2f;
  p.specTrans = 0.5f;
  p.flatness = 0.5f;
  p.diffTrans = 0.6f;
  expectValuesAlongMitsubasTestArc(PrincipledThinBSDF(p), values, pdfs, 1e-2, 1e-5);
}

TEST(PrincipledThin, BothSidesAreTheSameAndReflectionIsReciprocal) {
  // Transmission is not reciprocal: as in Mitsuba, a transmitted pair counts only where wo leaves
  // through the back of the half vector of wi and wo's mirror image, which is not symmetric in
  // the two directions.
  PrincipledThinParameters p = parameterSets().back().parameters;
  p.baseColor = SpectralDistribution::piecewiseLinear({400.0f, 700.0f}, {0.1f, 0.8f});
  PrincipledThinBSDF bsdf(p);
  const Wavelengths wl = testWavelengths();
  PCG32 rng(8, 8);
  for (int n = 0; n < 300; ++n) {
    Vec3 a = directionAt(85.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Vec3 b = directionAt(175.0f * rng.nextFloat(), 360.0f * rng.nextFloat());
    Vec3 aBelow(a.x, a.y, -a.z), bFlipped(b.x, b.y, -b.z);
    Spectrum fab = bsdf.eval(kContext, a, b, wl), flipped = bsdf.eval(kContext, aBelow, bFlipped, wl);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(fab[i], flipped[i], 1e-5f * std::max(1.0f, fab[i]));
    if (b.z < 0.0f) continue;
    Spectrum fba = bsdf.eval(kContext, b, a, wl) / a.z;
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(fab[i] / b.z, fba[i], 1e-4f * std::max(1.0f, fba[i]));
  }
}

TEST(PrincipledThin, SceneDefaultsAndMistakes) {
  const Wavelengths wl = testWavelengths();
  auto defaults = loadThin("");
  auto explicitDefaults = loadThin(R"(
    <float name="base_color" value="0.5"/> <float name="roughness" value="0.5"/> <float name="anisotropic" value="0"/>
    <float name="spec_trans" value="0"/> <float name="diff_trans" value="0"/> <float name="eta" value="1.5"/>
    <float name="spec_tint" value="0"/> <float name="sheen" value="0"/> <float name="sheen_tint" value="0"/>
    <float name="flatness" value="0"/> <float name="specular_reflectance_sampling_rate" value="1"/>
    <float name="specular_transmittance_sampling_rate" value="1"/>
    <float name="diffuse_reflectance_sampling_rate" value="1"/>
    <float name="diffuse_transmittance_sampling_rate" value="1"/>)");
  ASSERT_TRUE(defaults && explicitDefaults);
  // Grazing, where the roughness-driven retro-reflection shows.
  Vec3 wi = directionAt(70.0f), wo = directionAt(75.0f, 170.0f);
  float a = defaults->eval(kContext, wi, wo, wl)[0];
  EXPECT_GT(a, 0.0f);
  EXPECT_FLOAT_EQ(a, explicitDefaults->eval(kContext, wi, wo, wl)[0]);
  // By default the sheet is opaque and diffuse: nothing passes.
  EXPECT_EQ(defaults->eval(kContext, wi, -wo, wl)[0], 0.0f);

  EXPECT_NE(loadError(R"(<float name="diff_trans" value="2.5"/>)").find("diff_trans"), std::string::npos);
  EXPECT_NE(loadError(R"(<float name="specular" value="0.5"/>)").find("specular"), std::string::npos);
  EXPECT_NE(loadError(R"(<float name="spec_trans" value="-0.1"/>)").find("spec_trans"), std::string::npos);
}

TEST(PrincipledThin, TexturedParametersAreTakenAtTheShadingPoint) {
  const std::string constants = R"(<float name="spec_trans" value="0.4"/> <float name="sheen" value="0.5"/>)";
  auto textured = loadThin(constants + R"(
    <texture type="checkerboard" name="diff_trans"><float name="color0" value="0.9"/>
      <float name="color1" value="0.3"/></texture>
    <texture type="checkerboard" name="eta"><float name="color0" value="1.6"/>
      <float name="color1" value="1.2"/></texture>)");  // single values take the colours swapped
  auto first = std::dynamic_pointer_cast<BSDF>(
      loadThin(constants + R"(<float name="diff_trans" value="0.3"/> <float name="eta" value="1.2"/>)"));
  auto second = std::dynamic_pointer_cast<BSDF>(
      loadThin(constants + R"(<float name="diff_trans" value="0.9"/> <float name="eta" value="1.6"/>)"));
  ASSERT_TRUE(textured && first && second);
  const Wavelengths wl = testWavelengths();
  const BSDFContext inFirst{Vec2(0.25f, 0.25f), Vec3(), Vec3()}, inSecond{Vec2(0.75f, 0.25f), Vec3(), Vec3()};
  const Vec3 wi = directionAt(35.0f), wo = directionAt(50.0f, 160.0f), through = directionAt(150.0f, 200.0f);
  for (const Vec3& out : {wo, through}) {
    EXPECT_FLOAT_EQ(textured->eval(inFirst, wi, out, wl)[0], first->eval(inFirst, wi, out, wl)[0]);
    EXPECT_FLOAT_EQ(textured->eval(inSecond, wi, out, wl)[0], second->eval(inSecond, wi, out, wl)[0]);
    EXPECT_FLOAT_EQ(textured->pdf(inFirst, wi, out, wl), first->pdf(inFirst, wi, out, wl));
    EXPECT_FLOAT_EQ(textured->pdf(inSecond, wi, out, wl), second->pdf(inSecond, wi, out, wl));
  }
  EXPECT_NE(textured->eval(inFirst, wi, through, wl)[0], textured->eval(inSecond, wi, through, wl)[0]);
}
