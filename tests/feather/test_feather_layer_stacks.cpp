// A feather whose file gives each vertex a layer stack (`stack`) renders each barb with the
// barbule BSDF's stack of that number (`layers` for 0, `layers_1`, ... after it): renders against
// BSDFs that hold the chosen stack as their only one, and the messages for stacks a file chooses
// that the BSDF lacks, numbering gaps, and stacks no vertex can choose.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include "support/feather_test_util.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::renderSceneString;
using columba::testing::samePixels;

namespace {

constexpr const char* kThinMelanin = "melanin:0.05";
constexpr const char* kKeratinGap = "melanin:0.08, keratin:0.12, melanin:0.08";

class FeatherLayerStackTest : public columba::testing::TempDirTest {
 protected:
  // Eight straight barbs side by side along y (support/feather_test_util.h), every vertex of barb b
  // with layer stack stackOf(b); no stack property when stackOf is empty.
  std::string barbs(const std::function<int(int)>& stackOf, const std::string& name = "barbs.ply") {
    return columba::test::writeStraightBarbs((dir_ / name).string(), 0.6f, stackOf);
  }

  // The feather in `file` under a directional light, 24 x 24 pixels (a box filter, so that each
  // pixel sees only its own footprint), with the barbule BSDF (line 8) and its parameters `bsdf` from line 9.
  static std::string scene(const std::string& file, const std::string& bsdf) {
    return R"(<scene version="3.0.0">
<integrator type="direct"/>
<sensor type="perspective"><float name="fov" value="40"/>
  <transform name="to_world"><lookat origin="0, 0, 1.2" target="0, 0, 0" up="0, 1, 0"/></transform>
  <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/><rfilter type="box"/></film>
  <sampler type="independent"><integer name="sample_count" value="4"/></sampler></sensor>
<emitter type="directional"><vector name="direction" x="0.2" y="0.3" z="-1"/><spectrum name="irradiance" value="3"/></emitter>
<shape type="feather"><string name="filename" value=")" +
           file + R"("/><bsdf type="barbulebsdf">
)" + bsdf + "\n</bsdf></shape>\n</scene>";
  }

  static std::string layers(const std::string& name, const std::string& value) {
    return "<string name=\"" + name + "\" value=\"" + value + "\"/>";
  }

  std::string loadError(const std::string& xml) { return columba::test::sceneLoadError(xml, dir_.string()); }
};

// Rows [first, last) of an image, as floats.
std::vector<float> rows(const Image& image, int first, int last) {
  return std::vector<float>(image.rgb.begin() + 3 * image.width * first, image.rgb.begin() + 3 * image.width * last);
}

TEST_F(FeatherLayerStackTest, EachBarbRendersWithTheStackItsVerticesChoose) {
  // Every vertex choosing stack 1 is the BSDF with that stack as its only one, bit for bit.
  const Image allOne = renderSceneString(
      scene(barbs([](int) { return 1; }), layers("layers", kThinMelanin) + layers("layers_1", kKeratinGap)));
  const Image keratinGap = renderSceneString(scene(barbs({}), layers("layers", kKeratinGap)));
  const Image thinMelanin = renderSceneString(scene(barbs({}), layers("layers", kThinMelanin)));
  EXPECT_TRUE(samePixels(allOne, keratinGap));
  EXPECT_FALSE(samePixels(allOne, thinMelanin));

  // The upper four barbs (y > -0.03, the image's upper rows) choose stack 1, the lower four stack 0:
  // away from the boundary each half is the render of its stack alone.
  const Image halves = renderSceneString(scene(barbs([](int b) { return b >= 4 ? 1 : 0; }),
                                               layers("layers", kThinMelanin) + layers("layers_1", kKeratinGap)));
  EXPECT_EQ(rows(halves, 0, 10), rows(keratinGap, 0, 10));
  EXPECT_EQ(rows(halves, 14, 24), rows(thinMelanin, 14, 24));
  EXPECT_NE(rows(halves, 0, 10), rows(thinMelanin, 0, 10));
  EXPECT_NE(rows(halves, 14, 24), rows(keratinGap, 14, 24));
}

TEST_F(FeatherLayerStackTest, AStackTheBSDFLacksIsAnErrorNamingTheVertexAndTheBSDF) {
  const std::string file = barbs([](int b) { return b == 5 ? 2 : 1; });
  const std::string err = loadError(scene(file, layers("layers_1", kKeratinGap)));
  EXPECT_NE(err.find(file), std::string::npos) << err;
  EXPECT_NE(err.find("chooses layer stack 2 (vertex " + std::to_string(5 * kBarbVertices) + ")"), std::string::npos)
      << err;
  EXPECT_NE(err.find("scene.xml:8"), std::string::npos) << err;  // the barbulebsdf
  EXPECT_NE(err.find("stacks 0 to 1"), std::string::npos) << err;
  // Without numbered stacks, any stack but 0 is refused.
  EXPECT_NE(loadError(scene(barbs([](int) { return 1; }), "")).find("only stack 0"), std::string::npos);
  EXPECT_EQ(loadError(scene(barbs([](int) { return 0; }), "")), "");
}

TEST_F(FeatherLayerStackTest, NumberedStacksHaveNoGapsAndAreWarnedOfWhereNoVertexChoosesOne) {
  const std::string file = barbs([](int) { return 1; });
  const std::string err =
      loadError(scene(file, layers("layers_1", kKeratinGap) + "\n" + layers("layers_3", kThinMelanin)));
  EXPECT_NE(err.find("scene.xml:10"), std::string::npos) << err;
  EXPECT_NE(err.find("layers_3"), std::string::npos) << err;
  EXPECT_NE(err.find("layers_2 is missing"), std::string::npos) << err;

  // Said once, though the BSDF is reached twice through twosided and by two feathers.
  const std::string plain = barbs({}, "plain.ply");
  std::string twoFeathers = scene(plain, "\n" + layers("layers_1", kKeratinGap));
  const std::string opening = "<bsdf type=\"barbulebsdf\">";
  twoFeathers.replace(twoFeathers.find(opening), opening.size(),
                      "<bsdf type=\"twosided\"><bsdf type=\"barbulebsdf\" id=\"b\">");
  twoFeathers.replace(twoFeathers.find("</bsdf></shape>"), 15,
                      "</bsdf></bsdf></shape><shape type=\"feather\"><string name=\"filename\" value=\"" + plain +
                          "\"/><ref id=\"b\"/></shape>");
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(loadError(twoFeathers), "");
  const std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("scene.xml:10: barbulebsdf, parameter 'layers_1'"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("chooses no layer stack per vertex"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("warning:"), warnings.rfind("warning:")) << warnings;
  // A file whose vertices all choose stack 0 chooses: no warning.
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(loadError(scene(barbs([](int) { return 0; }), layers("layers_1", kKeratinGap))), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

}  // namespace
