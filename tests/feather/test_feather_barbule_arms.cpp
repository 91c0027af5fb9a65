// A feather with the barbule BSDF of arms: its per-vertex cortex thickness is used, its per-vertex
// tilt and spacing are warned of once (the cross-section is the same everywhere), and a layer stack
// other than 0 is refused naming the vertex and the BSDF.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include "support/feather_test_util.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using columba::testing::renderSceneString;
using columba::testing::samePixels;

namespace {

class FeatherBarbuleArmsTest : public columba::testing::TempDirTest {
 protected:
  // Eight straight barbs whose vertices give H, mu and the cortex thickness `height`.
  std::string barbs(float height, const std::function<int(int)>& stackOf = {}, const std::string& name = "barbs.ply") {
    return columba::test::writeStraightBarbs((dir_ / name).string(), height, stackOf);
  }
  // The feather under a directional light, 16 x 16 pixels, with a roof of three arms (line 8) and
  // its further parameters `bsdf`.
  static std::string scene(const std::string& file, const std::string& bsdf = "") {
    return R"(<scene version="3.0.0">
<integrator type="path"><integer name="max_depth" value="2"/></integrator>
<sensor type="perspective"><float name="fov" value="40"/>
  <transform name="to_world"><lookat origin="0, 0, 1.2" target="0, 0, 0" up="0, 1, 0"/></transform>
  <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/><rfilter type="box"/></film>
  <sampler type="independent"><integer name="sample_count" value="8"/></sampler></sensor>
<emitter type="constant"><spectrum name="radiance" value="1"/></emitter>
<shape type="feather"><string name="filename" value=")" +
           file + R"("/><bsdf type="barbulearms">
<string name="arm_tilts" value="-30, 0, 30"/>)" +
           bsdf + "\n</bsdf></shape>\n</scene>";
  }
  std::string loadError(const std::string& xml) { return columba::test::sceneLoadError(xml, dir_.string()); }
};

TEST_F(FeatherBarbuleArmsTest, TheFeathersThicknessIsUsedAndItsTiltAndSpacingAreWarnedOfOnce) {
  ::testing::internal::CaptureStderr();
  const Image thin = renderSceneString(scene(barbs(0.1f)));
  const std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(warnings.find("gives per-vertex 'mu' or 'H', which have no effect"), std::string::npos) << warnings;
  EXPECT_EQ(warnings.find("warning:"), warnings.rfind("warning:")) << warnings;
  double sum = 0.0;
  for (float v : thin.rgb) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
  }
  EXPECT_GT(sum, 0.0);
  // Another per-vertex thickness is another colour; the BSDF's own `height` is then shadowed,
  // which is said naming its line.
  ::testing::internal::CaptureStderr();
  const Image thick = renderSceneString(scene(barbs(0.5f, {}, "thick.ply"), "<float name=\"height\" value=\"0.1\"/>"));
  const std::string shadowed = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(samePixels(thin, thick));
  EXPECT_NE(shadowed.find("<test scene>:9: barbulearms, parameter 'height'"), std::string::npos) << shadowed;
  EXPECT_NE(shadowed.find("no effect on the feather"), std::string::npos) << shadowed;
}

TEST_F(FeatherBarbuleArmsTest, ALayerStackOtherThanTheFirstIsRefused) {
  const std::string file = barbs(0.3f, [](int b) { return b == 2 ? 1 : 0; });
  const std::string err = loadError(scene(file));
  EXPECT_NE(err.find("chooses layer stack 1 (vertex " + std::to_string(2 * kBarbVertices) + ")"), std::string::npos)
      << err;
  EXPECT_NE(err.find("barbulearms (scene.xml:8)"), std::string::npos) << err;
  EXPECT_EQ(loadError(scene(barbs(
                0.3f, [](int) { return 0; }, "zero.ply"))),
            "");
}

}  // namespace
