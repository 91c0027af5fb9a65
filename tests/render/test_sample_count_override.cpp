// A render asked for another sample count than its scene's sampler (`columba render --spp`, the
// Python API's spp) renders what the scene would with that sample_count: its samples are
// stratified among themselves, not the first ones of the scene's larger pattern.
#include <gtest/gtest.h>

#include <string>

#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

// A diffuse plane under a constant sky, BSDF sampling only: every pixel's noise comes from its
// samples' directions.
std::string skyLitPlane(const std::string& sampler, int sampleCount) {
  return R"(<scene version="3.0.0">
    <integrator type="direct"><integer name="emitter_samples" value="0"/><integer name="bsdf_samples" value="1"/></integrator>
    <sensor type="perspective"><float name="fov" value="30"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="16"/></film>
      <sampler type=")" +
         sampler + R"("><integer name="sample_count" value=")" + std::to_string(sampleCount) +
         R"("/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform><bsdf type="diffuse"/></shape>
    <emitter type="constant"><spectrum name="radiance" value="1"/></emitter>
  </scene>)";
}

Image render(const std::string& xml, int spp) {
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = 3;
  return renderSceneString(xml, settings);
}

}  // namespace

TEST(SampleCountOverride, RendersWhatTheSceneWouldWithThatSampleCount) {
  for (const char* sampler : {"ldsampler", "stratified", "multijitter", "independent"}) {
    SCOPED_TRACE(sampler);
    for (int spp : {4, 16}) {
      Image overridden = render(skyLitPlane(sampler, 64), spp);
      Image own = render(skyLitPlane(sampler, spp), spp);
      EXPECT_EQ(overridden.rgb, own.rgb) << spp << " spp";
    }
  }
}
