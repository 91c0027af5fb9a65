#include <gtest/gtest.h>

#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
// A camera looking straight down at the origin from `height` with a 1 degree field of view,
// so the visible patch is tiny and the lighting over it is uniform to 1e-4.
std::string cameraLookingDown(float height, int res, int spp, const std::string& sampler = "independent") {
  return R"(<sensor type="perspective"><float name="fov" value="1"/>
      <transform name="to_world"><lookat origin="0, 0, )" +
         std::to_string(height) +
         R"(" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value=")" +
         std::to_string(res) + R"("/>
        <integer name="height" value=")" +
         std::to_string(res) + R"("/><rfilter type="box"/></film>
      <sampler type=")" +
         sampler + R"("><integer name="sample_count" value=")" + std::to_string(spp) + R"("/></sampler>
    </sensor>)";
}

void expectGrey(const Vec3& c, float expected, float relTol) {
  EXPECT_NEAR(c.x, expected, relTol * expected);
  EXPECT_NEAR(c.y, expected, relTol * expected);
  EXPECT_NEAR(c.z, expected, relTol * expected);
}
}  // namespace

TEST(Integrator, WhiteFurnaceReturnsTheEnvironmentRadiance) {
  // An albedo-1 diffuse sphere in a uniform environment is invisible: every pixel sees 0.8.
  for (const char* integrator : {"path", "direct"}) {
    std::string xml = std::string(R"(<scene version="3.0.0"><integrator type=")") + integrator + R"("/>
      <sensor type="perspective"><float name="fov" value="30"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="32"/></film>
        <sampler type="ldsampler"><integer name="sample_count" value="256"/></sampler>
      </sensor>
      <shape type="sphere"><bsdf type="diffuse"><float name="reflectance" value="1"/></bsdf></shape>
      <emitter type="constant"><spectrum name="radiance" value="0.8"/></emitter></scene>)";
    Image image = renderSceneString(xml);
    Vec3 centre = meanColour(image, 12, 12, 20, 20);  // all on the sphere
    SCOPED_TRACE(integrator);
    expectGrey(centre, 0.8f, 0.01f);
  }
}

TEST(Integrator, DiffusePlaneUnderAPointLightMatchesTheClosedForm) {
  // L = rho / pi * I / h^2 directly below a point light of intensity I at height h.
  const float rho = 0.5f, intensity = 10.0f, h = 2.0f;
  for (const char* integrator : {"path", "direct"}) {
    std::string xml = std::string(R"(<scene version="3.0.0"><integrator type=")") + integrator + R"("/>)" +
                      cameraLookingDown(5.0f, 8, 64) + R"(
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
      <emitter type="point"><point name="position" x="0" y="0" z="2"/><spectrum name="intensity" value="10"/></emitter>
      </scene>)";
    SCOPED_TRACE(integrator);
    expectGrey(meanColour(renderSceneString(xml), 0, 0, 8, 8), rho / kPi * intensity / (h * h), 0.01f);
  }
}

TEST(Integrator, DiffusePlaneUnderADirectionalLightMatchesTheClosedForm) {
  // L = rho / pi * E * cos(theta) for irradiance E arriving at angle theta.
  const float rho = 0.5f, irradiance = 3.0f, cosTheta = std::cos(degToRad(60.0f));
  std::string xml = R"(<scene version="3.0.0"><integrator type="path"/>)" + cameraLookingDown(5.0f, 8, 64) + R"(
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
      <emitter type="directional"><vector name="direction" x=")" +
                    std::to_string(std::sin(degToRad(60.0f))) + R"(" y="0" z=")" + std::to_string(-cosTheta) +
                    R"("/><spectrum name="irradiance" value="3"/></emitter>
      </scene>)";
  expectGrey(meanColour(renderSceneString(xml), 0, 0, 8, 8), rho / kPi * irradiance * cosTheta, 0.01f);
}

TEST(Integrator, AreaLightSeenThroughMISMatchesEitherStrategyAlone) {
  // The direct integrator with only emitter sampling, only BSDF sampling and both must agree.
  auto render = [](int emitterSamples, int bsdfSamples) {
    std::string xml = R"(<scene version="3.0.0"><integrator type="direct">
        <integer name="emitter_samples" value=")" +
                      std::to_string(emitterSamples) + R"("/>
        <integer name="bsdf_samples" value=")" +
                      std::to_string(bsdfSamples) + R"("/></integrator>)" +
                      cameraLookingDown(5.0f, 8, 1024, "ldsampler") + R"(
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
      <shape type="disk"><transform name="to_world"><rotate x="1" angle="180"/><translate x="1" z="1.5"/></transform>
        <emitter type="area"><spectrum name="radiance" value="4"/></emitter></shape></scene>)";
    return meanColour(renderSceneString(xml), 0, 0, 8, 8).y;
  };
  float emitterOnly = render(1, 0), bsdfOnly = render(0, 1), both = render(1, 1);
  EXPECT_NEAR(bsdfOnly, emitterOnly, 0.03f * emitterOnly);
  EXPECT_NEAR(both, emitterOnly, 0.02f * emitterOnly);
}

// A constant environment beside an area light: with both kinds of samples, emitter sampling leaves
// the environment to the BSDF samples (Scene::EmitterSet) and draws only the light. Every mix of
// strategies must give the closed form L = rho (L_env (1 - k) + L_disk k), k = r^2 / (r^2 + h^2)
// the share of the hemisphere's projected solid angle that a disk of radius r at height h covers
// on its axis (and hides of the environment).
TEST(Integrator, ConstantEnvironmentBesideAnAreaLightMatchesTheClosedForm) {
  const float rho = 0.5f, environment = 0.8f, disk = 4.0f, h = 1.5f, k = 1.0f / (1.0f + h * h);
  const float expected = rho * (environment * (1.0f - k) + disk * k);
  auto render = [&](const std::string& integrator) {
    // The camera between the plane and the disk, which would hide the patch from above.
    std::string xml = R"(<scene version="3.0.0">)" + integrator + cameraLookingDown(1.0f, 8, 1024, "ldsampler") + R"(
      <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
        <bsdf type="diffuse"><float name="reflectance" value="0.5"/></bsdf></shape>
      <shape type="disk"><transform name="to_world"><rotate x="1" angle="180"/><translate z="1.5"/></transform>
        <emitter type="area"><spectrum name="radiance" value="4"/></emitter></shape>
      <emitter type="constant"><spectrum name="radiance" value="0.8"/></emitter></scene>)";
    return meanColour(renderSceneString(xml), 0, 0, 8, 8);
  };
  auto direct = [](int emitterSamples, int bsdfSamples) {
    return R"(<integrator type="direct"><integer name="emitter_samples" value=")" + std::to_string(emitterSamples) +
           R"("/><integer name="bsdf_samples" value=")" + std::to_string(bsdfSamples) + R"("/></integrator>)";
  };
  // The path integrator stops after the first vertex: the disk's own diffuse back would reflect
  // the plane's light into it, which the closed form leaves out.
  // With emitter_candidates, the path integrator draws 3 emitter samples and traces the one its
  // resampling chooses.
  for (const std::string& integrator :
       {std::string(R"(<integrator type="path"><integer name="max_depth" value="2"/></integrator>)"),
        std::string(R"(<integrator type="path"><integer name="max_depth" value="2"/>
                       <integer name="emitter_candidates" value="3"/></integrator>)"),
        direct(1, 1), direct(1, 0), direct(0, 1)}) {
    SCOPED_TRACE(integrator);
    expectGrey(render(integrator), expected, 0.015f);
  }
}

TEST(Renderer, ImagesAreBitIdenticalForAnyThreadCount) {
  std::string xml = R"(<scene version="3.0.0"><integrator type="path"/>
      <sensor type="perspective"><transform name="to_world"><lookat origin="0, -4, 2" target="0, 0, 0.5" up="0, 0, 1"/></transform>
        <film type="hdrfilm"><integer name="width" value="48"/><integer name="height" value="40"/></film>
        <sampler type="ldsampler"><integer name="sample_count" value="8"/></sampler></sensor>
      <shape type="sphere"><point name="center" x="0" y="0" z="0.7"/><float name="radius" value="0.7"/>
        <bsdf type="roughconductor"><float name="alpha" value="0.2"/></bsdf></shape>
      <shape type="rectangle"><transform name="to_world"><scale value="5"/></transform></shape>
      <emitter type="constant"><spectrum name="radiance" value="1"/></emitter></scene>)";
  RenderSettings one, two, otherSeed;
  one.threads = 1;
  two.threads = 2;
  otherSeed.threads = 2;
  otherSeed.seed = 7;
  Image a = renderSceneString(xml, one), b = renderSceneString(xml, two), c = renderSceneString(xml, otherSeed);
  EXPECT_EQ(a.rgb, b.rgb);
  EXPECT_NE(a.rgb, c.rgb);
}

TEST(Renderer, CancellingKeepsTheImageSizeAndReportsIncomplete) {
  std::atomic<bool> cancel{true};
  RenderSettings settings;
  settings.cancel = &cancel;
  RenderStats stats;
  Image image = renderSceneString(R"(<scene version="3.0.0"><emitter type="constant"/></scene>)", settings, &stats);
  EXPECT_FALSE(stats.complete);
  EXPECT_EQ(image.width, 768);
  EXPECT_EQ(image.height, 576);
}

namespace {
// A small scene: a sphere on a plane under uniform light, with the given integrator and sensor
// elements and `more` after them.
std::string sphereOnAPlane(const std::string& integrator, const std::string& sensor, const std::string& more = "") {
  return "<scene version=\"3.0.0\">\n" + integrator + "\n" + sensor + "\n" + more + R"(
      <shape type="sphere"><point name="center" x="0" y="0" z="0.7"/><float name="radius" value="0.7"/></shape>
      <shape type="rectangle"><transform name="to_world"><scale value="5"/></transform></shape>
      <emitter type="constant"><spectrum name="radiance" value="1"/></emitter></scene>)";
}
const char* const kLookAtTheSphere =
    R"(<transform name="to_world"><lookat origin="0, -4, 2" target="0, 0, 0.5" up="0, 0, 1"/></transform>)";
}  // namespace

TEST(Renderer, MitsubaPassParametersLeaveTheImageAlone) {
  const std::string sensor =
      std::string("<sensor type=\"perspective\">") + kLookAtTheSphere +
      R"(<film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="12"/></film>
        <sampler type="independent"><integer name="sample_count" value="4"/></sampler></sensor>)";
  Image plain = renderSceneString(sphereOnAPlane("<integrator type=\"path\"/>", sensor));
  ::testing::internal::CaptureStderr();
  Image passes =
      renderSceneString(sphereOnAPlane("<integrator type=\"path\"><integer name=\"samples_per_pass\" value=\"2\"/>\n"
                                       "<float name=\"timeout\" value=\"30\"/></integrator>",
                                       sensor));
  const std::string warnings = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(plain.rgb, passes.rgb);
  EXPECT_NE(warnings.find("<test scene>:3: timeout is ignored"), std::string::npos) << warnings;
}

TEST(Renderer, ASensorMayReferenceATopLevelFilmAndSampler) {
  const std::string film =
      R"(<film type="hdrfilm" id="f"><integer name="width" value="24"/><integer name="height" value="16"/></film>)";
  const std::string sampler =
      R"(<sampler type="independent" id="s"><integer name="sample_count" value="4"/></sampler>)";
  const std::string sensor = std::string("<sensor type=\"perspective\">") + kLookAtTheSphere;
  Image nested =
      renderSceneString(sphereOnAPlane("<integrator type=\"path\"/>", sensor + film + sampler + "</sensor>"));
  // The sampler declared before the sensor, the film after it.
  Image referenced = renderSceneString(sphereOnAPlane("<integrator type=\"path\"/>" + sampler,
                                                      sensor + "<ref id=\"f\"/><ref id=\"s\"/></sensor>", film));
  EXPECT_EQ(referenced.width, 24);
  EXPECT_EQ(referenced.height, 16);
  EXPECT_EQ(nested.rgb, referenced.rgb);
}
