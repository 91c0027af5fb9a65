// `moment` renders the integrator nested in it (Mitsuba's first moment), saying that the second
// moment is not recorded; without exactly one nested integrator it is an error naming the line.
#include <gtest/gtest.h>

#include "builtin/builtin_plugins.h"
#include "core/error.h"
#include "scene/scene_loader.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
std::string sceneWith(const std::string& integrator) {
  return R"(<scene version="3.0.0">)" + integrator + R"(
  <sensor type="perspective"><transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film>
    <sampler type="independent"><integer name="sample_count" value="16"/></sampler></sensor>
  <shape type="sphere"><bsdf type="diffuse"/></shape>
  <emitter type="constant"/>
</scene>)";
}
}  // namespace

TEST(MomentIntegrator, RendersItsNestedIntegratorAndSaysWhatItLeavesOut) {
  const std::string path = R"(<integrator type="path"><integer name="max_depth" value="3"/></integrator>)";
  RenderSettings settings;
  settings.seed = 3;
  const Image plain = renderSceneString(sceneWith(path), settings);
  ::testing::internal::CaptureStderr();
  const Image wrapped =
      renderSceneString(sceneWith(R"(<integrator type="moment">)" + path + "</integrator>"), settings);
  const std::string warned = ::testing::internal::GetCapturedStderr();
  EXPECT_TRUE(samePixels(plain, wrapped));
  EXPECT_NE(warned.find("second moment"), std::string::npos) << warned;
  try {
    loadSceneString(sceneWith(R"(<integrator type="moment"/>)"), "m.xml", ".", {}, builtinPlugins());
    ADD_FAILURE() << "an empty moment was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("m.xml:1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("exactly one nested integrator"), std::string::npos) << e.what();
  }
}
