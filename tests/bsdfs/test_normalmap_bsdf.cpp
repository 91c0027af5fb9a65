#include <gtest/gtest.h>

#include <cmath>

#include "bsdfs/diffuse.h"
#include "bsdfs/normalmap.h"
#include "builtin/builtin_plugins.h"
#include "io/image.h"
#include "scene/scene.h"
#include "support/bsdf_test_support.h"
#include "support/error_test_support.h"
#include "support/temp_dir_test.h"
#include "textures/bitmap_texture.h"
#include "textures/raw_constant_texture.h"

using namespace columba;
using namespace columba::testing;

namespace {

class NormalMap : public TempDirTest {
 protected:
  // A one-texel normal map storing the normal n as the colour (n + 1) / 2, read raw.
  std::shared_ptr<const BitmapTexture> mapOf(const Vec3& n) {
    Image texel(1, 1);
    texel.rgb = {0.5f * (n.x + 1.0f), 0.5f * (n.y + 1.0f), 0.5f * (n.z + 1.0f)};
    const std::string path = (dir_ / "normal.exr").string();
    writeEXR(path, texel);
    return std::make_shared<BitmapTexture>(readImagePixels(path, false), true, TextureFilter::Bilinear,
                                           TextureWrap::Repeat, Transform());
  }
  std::shared_ptr<BSDF> diffuse() { return std::make_shared<DiffuseBSDF>(SpectralDistribution::constant(0.5f)); }
};

const float kTilt = 30.0f * kPi / 180.0f;
const Vec3 kTilted(std::sin(kTilt), 0.0f, std::cos(kTilt));

}  // namespace

TEST_F(NormalMap, AFlatMapLeavesTheNestedBSDF) {
  NormalMapBSDF flat(diffuse(), mapOf(Vec3(0, 0, 1)));
  auto plain = diffuse();
  const Wavelengths wl = testWavelengths();
  const Vec3 wi = directionAt(20, 30), wo = directionAt(50, 200);
  EXPECT_NEAR(flat.eval({}, wi, wo, wl)[0], plain->eval({}, wi, wo, wl)[0], 1e-6f);
  EXPECT_NEAR(flat.pdf({}, wi, wo, wl), plain->pdf({}, wi, wo, wl), 1e-6f);
}

TEST_F(NormalMap, ATiltedNormalShadesAsTheDiffuseClosedForm) {
  NormalMapBSDF tilted(diffuse(), mapOf(kTilted));
  const Wavelengths wl = testWavelengths();
  const Vec3 wi = directionAt(10, 0);
  // Lambert about the tilted normal: 0.5 / pi * (wo . n).
  for (Vec3 wo : {directionAt(40, 0), directionAt(60, 90), directionAt(20, 180)}) {
    EXPECT_NEAR(tilted.eval({}, wi, wo, wl)[0], 0.5f * kInvPi * std::max(0.0f, dot(wo, kTilted)), 1e-6f);
    EXPECT_NEAR(tilted.pdf({}, wi, wo, wl), kInvPi * std::max(0.0f, dot(wo, kTilted)), 1e-6f);
  }
  // Above the tilted surface but below the real one: no light leaks through.
  const Vec3 leak = normalize(Vec3(0.9f, 0.0f, -0.2f));
  ASSERT_GT(dot(leak, kTilted), 0.0f);
  EXPECT_EQ(tilted.eval({}, wi, leak, wl)[0], 0.0f);
  EXPECT_EQ(tilted.pdf({}, wi, leak, wl), 0.0f);
}

TEST_F(NormalMap, ARawConstantTripleIsAMapToo) {
  // Mitsuba's rawconstant with three values gives them as they are: (n + 1) / 2 is the normal n.
  NormalMapBSDF tilted(diffuse(), std::make_shared<RawConstantTexture>((kTilted + Vec3(1, 1, 1)) * 0.5f));
  const Wavelengths wl = testWavelengths();
  const Vec3 wi = directionAt(10, 0);
  for (Vec3 wo : {directionAt(40, 0), directionAt(60, 90), directionAt(20, 180)})
    EXPECT_NEAR(tilted.eval({}, wi, wo, wl)[0], 0.5f * kInvPi * std::max(0.0f, dot(wo, kTilted)), 1e-6f);
}

TEST_F(NormalMap, SamplingMatchesThePdf) {
  NormalMapBSDF tilted(diffuse(), mapOf(kTilted));
  const double threshold = sidakThreshold(0.01, 3);
  for (float theta : {0.0f, 45.0f, 75.0f}) {
    ChiSquareResult r = chiSquareBSDF(tilted, directionAt(theta, 30));
    EXPECT_GT(r.pValue, threshold) << theta << ": " << r.message;
  }
  EXPECT_LT(maxWeightError(tilted, directionAt(45, 30)), 1e-4);
}

TEST_F(NormalMap, TheMapMustGiveRawTriples) {
  Image texel(1, 1);
  texel.rgb = {0.5f, 0.5f, 1.0f};
  writeEXR((dir_ / "n.exr").string(), texel);
  auto errorOf = [&](const std::string& raw) {
    try {
      loadSceneString(R"(<scene version="3.0.0">
<bsdf type="normalmap"><texture type="bitmap" name="normalmap"><string name="filename" value="n.exr"/>)" +
                          raw + "</texture><bsdf type=\"diffuse\"/></bsdf></scene>",
                      (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(errorOf("<boolean name=\"raw\" value=\"true\"/>"), "");
  expectContains(errorOf(""), {"t.xml:2", "read with raw=true"});
  try {
    loadSceneString(R"(<scene version="3.0.0">
<bsdf type="normalmap"><texture type="checkerboard" name="normalmap"/><bsdf type="diffuse"/></bsdf></scene>)",
                    (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    ADD_FAILURE() << "a checkerboard was taken as a normal map";
  } catch (const InputError& e) {
    expectContains(e.what(), {"t.xml:2", "must give raw triples"});
  }
}
