#include <gtest/gtest.h>

#include <filesystem>

#include "builtin/builtin_plugins.h"
#include "core/illuminant.h"
#include "core/sampling.h"
#include "emitters/envmap_emitter.h"
#include "io/image.h"
#include "scene/scene.h"
#include "support/chi_square.h"
#include "support/image_test_support.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {
constexpr double kFamilyAlpha = 0.01;

// An environment map with a bright blob, a dim band and a dark rest.
Image testEnvironment() {
  Image img(64, 32);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float* p = img.pixel(x, y);
      float v =
          0.05f + (y > 20 && y < 26 ? 0.5f : 0.0f) + ((x - 40) * (x - 40) + (y - 10) * (y - 10) < 20 ? 20.0f : 0.0f);
      p[0] = v;
      p[1] = 0.8f * v;
      p[2] = 0.6f * v;
    }
  return img;
}

Wavelengths someWavelengths() { return Wavelengths::fixed({450, 530, 610, 680}); }
}  // namespace

TEST(Emitter, EnvmapSamplingMatchesItsPdfSlow) {
  EnvmapEmitter env(testEnvironment(), 1.0f, Transform::rotate(Vec3(1, 0, 0), 30.0f));
  Wavelengths wl = someWavelengths();
  auto result = chiSquareDirectionTest(
      [&](PCG32& rng) -> std::optional<Vec3> {
        auto s = env.sample(Vec3(), Vec2(rng.nextFloat(), rng.nextFloat()), wl);
        if (!s) return std::nullopt;
        return s->direction;
      },
      [&](const Vec3& d) { return double(env.pdfDirection(d)); }, 400000, 32, 64, 16);
  std::cout << "envmap: " << result.message << "\n";
  EXPECT_GT(result.pValue, kFamilyAlpha);
}

TEST(Emitter, EnvmapSampleRadianceOverPdfIntegratesTheMapSlow) {
  // E[L / pdf] over sampled directions is the integral of L over the sphere; compare it with
  // uniform-sphere integration of the same radiance.
  EnvmapEmitter env(testEnvironment(), 2.0f, Transform());
  Wavelengths wl = someWavelengths();
  PCG32 rng(3, 4);
  double importance = 0, uniform = 0;
  const int n = 400000;
  for (int i = 0; i < n; ++i) {
    if (auto s = env.sample(Vec3(), Vec2(rng.nextFloat(), rng.nextFloat()), wl)) importance += s->radiance[1] / s->pdf;
    Vec3 d = sampleUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
    uniform += env.radianceFromDirection(d, wl)[1] / uniformSpherePdf();
  }
  EXPECT_NEAR(importance / n, uniform / n, 0.03 * uniform / n);
}

namespace {
// A directory of its own holding flat.exr, a 16 x 8 environment map of 0.6 everywhere.
std::filesystem::path directoryWithFlatEnvironment(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Image flat(16, 8);
  std::fill(flat.rgb.begin(), flat.rgb.end(), 0.6f);
  writeEXR((dir / "flat.exr").string(), flat);
  return dir;
}
}  // namespace

TEST(Emitter, UniformEnvmapIsAWhiteFurnace) {
  const auto dir = directoryWithFlatEnvironment("columba_env");
  std::string xml = R"(<scene version="3.0.0"><integrator type="path"/>
      <sensor type="perspective"><float name="fov" value="30"/>
        <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
        <sampler type="ldsampler"><integer name="sample_count" value="256"/></sampler></sensor>
      <shape type="sphere"><bsdf type="diffuse"><float name="reflectance" value="1"/></bsdf></shape>
      <emitter type="envmap"><string name="filename" value=")" +
                    (dir / "flat.exr").string() + R"("/></emitter></scene>)";
  Vec3 c = meanColour(renderSceneString(xml), 6, 6, 10, 10);
  std::filesystem::remove_all(dir);
  EXPECT_NEAR(c.x, 0.6f, 0.006f);
  EXPECT_NEAR(c.y, 0.6f, 0.006f);
  EXPECT_NEAR(c.z, 0.6f, 0.006f);
}

TEST(Emitter, AnEnvmapTurnsAndMirrorsButDoesNotScaleOrShear) {
  // Its directions are drawn with their density in the map's frame, which only a rigid to_world
  // keeps.
  const auto dir = directoryWithFlatEnvironment("columba_env_rigid");
  auto load = [&](const std::string& operations) {
    loadSceneString(R"(<scene version="3.0.0">
      <emitter type="envmap"><string name="filename" value=")" +
                        (dir / "flat.exr").string() + R"("/><transform name="to_world">)" + operations +
                        "</transform></emitter></scene>",
                    "<test>", ".", {}, builtinPlugins());
  };
  EXPECT_NO_THROW(load(R"(<rotate x="0.6" y="0.8" angle="40"/><scale x="-1"/>)"));
  for (const char* operations : {R"(<scale x="2"/>)", R"(<rotate x="1" y="1" angle="23"/>)"}) {
    try {
      load(operations);
      ADD_FAILURE() << "accepted " << operations;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("<test>:2"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("to_world must not scale or shear"), std::string::npos) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(Emitter, AreaLightDirectionSamplingMatchesPdfHitSlow) {
  // For each emitter shape, directions sampled from a reference point are tested against the
  // density pdfHit reports for the point a ray in that direction hits. The lights sit away from
  // the binning's pole, where bins are thin wedges the quadrature resolves poorly.
  const char* shapes[] = {
      R"(<shape type="disk"><transform name="to_world"><scale x="0.7" y="0.4" z="1"/><rotate x="1" angle="150"/><translate z="1.5"/></transform>)",
      R"(<shape type="rectangle"><transform name="to_world"><rotate x="1" angle="200"/><translate x="0.5" z="1"/></transform>)",
      R"(<shape type="sphere"><point name="center" x="2" y="0.5" z="0.3"/><float name="radius" value="0.6"/>)",
      // A <rotate> about an axis that is not unit length scales and shears (docs/transforms.md).
      R"(<shape type="disk"><transform name="to_world"><scale x="0.5" y="0.3" z="1"/><rotate x="1" y="1" angle="23"/>
          <rotate x="1" angle="180"/><translate x="-1.2" y="0.4" z="1"/></transform>)",
  };
  int tests = 4;
  for (const char* shape : shapes) {
    std::string xml = std::string(R"(<scene version="3.0.0">)") + shape +
                      R"(<emitter type="area"><spectrum name="radiance" value="1"/></emitter></shape></scene>)";
    ParsedScene parsed = loadSceneString(xml, "<test>", ".", {}, builtinPlugins());
    Scene scene(parsed, {"<test>", 0});
    const Emitter& emitter = *scene.emitters().front();
    Vec3 ref(0.1f, 0.05f, 0.0f);
    Wavelengths wl = someWavelengths();
    auto result = chiSquareDirectionTest(
        [&](PCG32& rng) -> std::optional<Vec3> {
          auto s = emitter.sample(ref, Vec2(rng.nextFloat(), rng.nextFloat()), wl);
          if (!s) return std::nullopt;
          // Only the first surface along the direction counts (a sphere's far side is hidden).
          auto hit = scene.intersect(Ray{ref, s->direction});
          if (!hit || std::abs(hit->t - s->distance) > 1e-3f * s->distance) return std::nullopt;
          return s->direction;
        },
        [&](const Vec3& d) {
          auto hit = scene.intersect(Ray{ref, d});
          return hit ? double(emitter.pdfHit(ref, *hit)) : 0.0;
        },
        200000, 40, 80, 16);
    std::cout << shape << "\n  " << result.message << "\n";
    EXPECT_GT(result.pValue, 1.0 - std::pow(1.0 - kFamilyAlpha, 1.0 / tests));
  }
}

TEST(Emitter, SpotFallsOffLinearlyInAngleAsMitsubas) {
  // Pointing from (1, 1, 1) toward +y; cutoff 40 degrees, beam width 20: full to 20 degrees off the
  // axis, half at 30, nothing from 40.
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0"><emitter type="spot">
      <float name="cutoff_angle" value="40"/><float name="beam_width" value="20"/>
      <transform name="to_world"><lookat origin="1, 1, 1" target="1, 2, 1" up="0, 0, 1"/></transform></emitter>
      <emitter type="point"><point name="position" x="1" y="1" z="1"/></emitter></scene>)",
                                       "<test>", ".", {}, builtinPlugins());
  auto spot = std::dynamic_pointer_cast<Emitter>(parsed.objects.at(0));
  auto point = std::dynamic_pointer_cast<Emitter>(parsed.objects.at(1));
  ASSERT_TRUE(spot && point);
  Wavelengths wl = someWavelengths();
  auto at = [&](float degrees, float distance) {
    float a = degToRad(degrees);
    return Vec3(1.0f + distance * std::sin(a), 1.0f + distance * std::cos(a), 1.0f);
  };
  // On the axis the spot equals a point light of the same intensity, 1 / r^2 included.
  auto onAxis = spot->sample(at(0, 2), Vec2(0.5f, 0.5f), wl);
  auto pointSample = point->sample(at(0, 2), Vec2(0.5f, 0.5f), wl);
  ASSERT_TRUE(onAxis && pointSample);
  EXPECT_NEAR(onAxis->distance, 2.0f, 1e-6f);
  EXPECT_NEAR(onAxis->direction.y, -1.0f, 1e-6f);
  for (int k = 0; k < kSpectrumSamples; ++k) EXPECT_FLOAT_EQ(onAxis->radiance[k], pointSample->radiance[k]);
  for (auto [degrees, expected] :
       {std::pair{10.0f, 1.0f}, {19.9f, 1.0f}, {25.0f, 0.75f}, {30.0f, 0.5f}, {35.0f, 0.25f}}) {
    auto s = spot->sample(at(degrees, 2), Vec2(0.5f, 0.5f), wl);
    ASSERT_TRUE(s) << degrees;
    EXPECT_NEAR(s->radiance[0] / onAxis->radiance[0], expected, 1e-4f) << degrees << " degrees";
  }
  EXPECT_FALSE(spot->sample(at(40.5f, 2), Vec2(0.5f, 0.5f), wl));
  EXPECT_FALSE(spot->sample(at(180.0f, 2), Vec2(0.5f, 0.5f), wl));  // behind it

  auto load = [](const std::string& params) {
    loadSceneString("<scene version=\"3.0.0\">\n<emitter type=\"spot\">\n" + params + "</emitter></scene>", "s.xml",
                    ".", {}, builtinPlugins());
  };
  load("<float name=\"cutoff_angle\" value=\"30\"/>");                          // beam width 22.5 by default
  EXPECT_THROW(load("<float name=\"beam_width\" value=\"25\"/>"), InputError);  // wider than the 20-degree cutoff
  EXPECT_THROW(load("<float name=\"cutoff_angle\" value=\"0\"/>"), InputError);
}

namespace {
// A projector of the scene body `params`, loaded from a scene file in `dir`.
std::shared_ptr<Emitter> projector(const std::string& params, const std::string& dir = ".") {
  ParsedScene parsed =
      loadSceneString(R"(<scene version="3.0.0"><emitter type="projector">)" + params + "</emitter></scene>",
                      dir + "/t.xml", dir, {}, builtinPlugins());
  return std::dynamic_pointer_cast<Emitter>(parsed.objects.at(0));
}
}  // namespace

TEST(Emitter, AProjectorLightsAsMitsubasWritesIt) {
  // Irradiance 0.5 through a 90-degree field of view (image half extents tan 45 = 1): a point at
  // (x, y, z) in the projector's frame receives pi * 0.5 * D65 / (z^2 cos theta) along the
  // direction from the projector, so that a plane facing it at z = 1 is lit evenly.
  auto light = projector(R"(<float name="fov" value="90"/><float name="irradiance" value="0.5"/>)");
  ASSERT_TRUE(light);
  EXPECT_TRUE(light->isDelta());
  const Wavelengths wl = someWavelengths();
  for (Vec3 p : {Vec3(0, 0, 1), Vec3(0.3f, -0.2f, 2.0f), Vec3(-0.9f, 0.9f, 1.0f)}) {
    auto s = light->sample(p, Vec2(0.5f, 0.5f), wl);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->distance, length(p), 1e-5f);
    const float cosTheta = p.z / length(p);
    for (int i = 0; i < kSpectrumSamples; ++i)
      EXPECT_NEAR(s->radiance[i] * p.z * p.z * cosTheta, kPi * 0.5f * d65(wl[i]), 1e-4f * d65(wl[i]));
  }
  // Outside the field of view, and behind the projector: nothing.
  EXPECT_FALSE(light->sample(Vec3(3.0f, 0.0f, 2.0f), Vec2(0.5f, 0.5f), wl));
  EXPECT_FALSE(light->sample(Vec3(0.0f, 0.0f, -1.0f), Vec2(0.5f, 0.5f), wl));
  // `scale` multiplies it.
  auto brighter = projector(R"(<float name="fov" value="90"/><float name="irradiance" value="0.5"/>
    <float name="scale" value="3"/>)");
  EXPECT_NEAR(
      brighter->sample(Vec3(0, 0, 1), Vec2(), wl)->radiance[0] / light->sample(Vec3(0, 0, 1), Vec2(), wl)->radiance[0],
      3.0f, 1e-5f);
}

TEST(Emitter, AProjectorShowsItsImageTheWayTheCameraSeesIt) {
  // Texels 0.25 (left) and 1 (right) of a 2 x 1 image, so the image plane's half extents are 1 in
  // x and 1/2 in y at fov 90. As the perspective camera maps its film, the image's left lies on the
  // projector's +x side: (1/2, 0, 1) meets the left texel's centre and (-1/2, 0, 1) the right's.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "columba_projector_test";
  std::filesystem::create_directories(dir);
  writeTwoTexelEXR((dir / "slide.exr").string(), 0.25f, 1.0f);
  auto light = projector(R"(<float name="fov" value="90"/>
    <texture type="bitmap" name="irradiance"><string name="filename" value="slide.exr"/>
      <string name="filter_type" value="nearest"/></texture>)",
                         dir.string());
  const Wavelengths wl = someWavelengths();
  auto left = light->sample(Vec3(0.5f, 0, 1), Vec2(), wl), right = light->sample(Vec3(-0.5f, 0, 1), Vec2(), wl);
  ASSERT_TRUE(left && right);
  for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(right->radiance[i] / left->radiance[i], 4.0f, 1e-4f);
  // The image's aspect is the texture's: at fov 90 its half height is 1/2.
  EXPECT_TRUE(light->sample(Vec3(0, 0.45f, 1), Vec2(), wl));
  EXPECT_FALSE(light->sample(Vec3(0, 0.55f, 1), Vec2(), wl));
  std::filesystem::remove_all(dir);
}

TEST(Emitter, AProjectorNeedsItsImage) {
  try {
    projector("");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs its 'irradiance'"), std::string::npos) << e.what();
  }
  try {
    projector(R"(<float name="irradiance" value="1"/><transform name="to_world"><scale value="2"/></transform>)");
    ADD_FAILURE() << "a scaling to_world was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("must not scale"), std::string::npos) << e.what();
  }
}
