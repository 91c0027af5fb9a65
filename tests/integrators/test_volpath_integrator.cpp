// volpath and volpathmis in scenes without participating media render what path renders; a scene
// with a medium is refused where the medium is.
#include <gtest/gtest.h>

#include "support/error_test_support.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// A glossy sphere on a diffuse plane under an area light, seen by a 24 x 18 camera, with
// `integrator` as the scene's integrator element and `extra` added to the scene.
std::string sphereScene(const std::string& integrator, const std::string& extra = "") {
  return R"(<scene version="3.0.0">
  )" + integrator +
         R"(
  <sensor type="perspective"><float name="fov" value="45"/>
    <transform name="to_world"><lookat origin="0, -3, 1.2" target="0, 0, 0.5" up="0, 0, 1"/></transform>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="18"/></film>
    <sampler type="independent"><integer name="sample_count" value="8"/></sampler></sensor>
  <shape type="sphere"><point name="center" x="0" y="0" z="0.5"/><float name="radius" value="0.5"/>
    <bsdf type="roughplastic"><rgb name="diffuse_reflectance" value="0.2, 0.5, 0.7"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="2"/></transform><bsdf type="diffuse"/></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="0.4"/><rotate x="1" angle="180"/><translate z="2.5"/></transform>
    <emitter type="area"><spectrum name="radiance" value="8"/></emitter></shape>
)" + extra +
         R"(
</scene>)";
}

std::string loadError(const std::string& xml) {
  try {
    loadSceneString(xml, "vol.xml", ".", {}, builtinPlugins());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(VolumetricPath, WithoutMediaRendersWhatPathRendersBitForBit) {
  RenderSettings settings;
  settings.seed = 11;
  const std::string parameters = R"(<integer name="max_depth" value="4"/><integer name="rr_depth" value="2"/>
    <boolean name="hide_emitters" value="true"/>)";
  const Image path =
      renderSceneString(sphereScene(R"(<integrator type="path">)" + parameters + "</integrator>"), settings);
  // The parameters matter, so the comparison would see them ignored.
  EXPECT_FALSE(samePixels(path, renderSceneString(sphereScene(R"(<integrator type="path"/>)"), settings)));
  for (const char* type : {"volpath", "volpathmis"}) {
    const Image volpath = renderSceneString(
        sphereScene(std::string("<integrator type=\"") + type + "\">" + parameters + "</integrator>"), settings);
    EXPECT_TRUE(samePixels(path, volpath)) << type;
  }
}

TEST(VolumetricPath, ScenesWithMediaAreRefusedNamingFileAndLine) {
  // A medium referenced as a shape's interior, and one nested in a shape, are refused where they are.
  expectContains(loadError(sphereScene(R"(<integrator type="volpath"/>)", R"(<medium type="homogeneous" id="fog"/>
  <shape type="sphere"><ref name="interior" id="fog"/><bsdf type="null"/></shape>)")),
                 {"vol.xml:12", "<medium type='homogeneous'>", "participating media are not supported yet"});
  expectContains(loadError(sphereScene(R"(<integrator type="volpathmis"/>)", R"(<shape type="sphere">
    <medium type="heterogeneous" name="exterior"/></shape>)")),
                 {"vol.xml:13", "<medium type='heterogeneous'>", "participating media are not supported yet"});
  // A volpath parameter volpath does not have is unknown, as in Mitsuba.
  expectContains(
      loadError(sphereScene(R"(<integrator type="volpath"><string name="strategy" value="bsdf"/></integrator>)")),
      {"vol.xml:2", "strategy"});
}
