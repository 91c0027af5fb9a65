// The orthographic camera as Mitsuba 3 defines it: film position (x, y) in [0, 1]^2 of the film
// starts its ray at the camera-space point (1 - 2x, (1 - 2y) / aspect, near_clip), along +z, for
// far_clip - near_clip; to_world places (and may size) that plane.
#include <gtest/gtest.h>

#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "sensors/orthographic_sensor.h"

using namespace columba;

namespace {

// A 40 x 20 orthographic sensor (aspect 2) with the given parameters.
std::shared_ptr<OrthographicSensor> sensorWith(const std::string& parameters) {
  const std::string xml = "<scene version=\"3.0.0\"><sensor type=\"orthographic\">" + parameters +
                          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"40\"/>"
                          "<integer name=\"height\" value=\"20\"/></film></sensor></scene>";
  ParsedScene scene = loadSceneString(xml, "test.xml", "", {}, builtinPlugins());
  auto sensor = std::dynamic_pointer_cast<OrthographicSensor>(scene.objects.at(0));
  if (!sensor) throw std::logic_error("not an orthographic sensor");
  return sensor;
}

void expectNear(const Vec3& a, const Vec3& b, const char* what) {
  EXPECT_NEAR(a.x, b.x, 1e-5f) << what;
  EXPECT_NEAR(a.y, b.y, 1e-5f) << what;
  EXPECT_NEAR(a.z, b.z, 1e-5f) << what;
}

}  // namespace

TEST(OrthographicSensor, RaysStartOnTheNearPlaneAlongZ) {
  auto sensor = sensorWith(R"(<float name="near_clip" value="0.5"/><float name="far_clip" value="7"/>)");
  // Pixel (0, 0)'s centre: x = 0.5/40, y = 0.5/20, so (1 - 0.025, (1 - 0.05) / 2, 0.5).
  std::optional<Ray> corner = sensor->generateRay(Vec2(0.5f, 0.5f));
  ASSERT_TRUE(corner.has_value());
  expectNear(corner->o, Vec3(0.975f, 0.475f, 0.5f), "corner origin");
  expectNear(corner->d, Vec3(0, 0, 1), "direction");
  EXPECT_FLOAT_EQ(corner->tmin, 0.0f);
  EXPECT_FLOAT_EQ(corner->tmax, 6.5f);
  // The film's centre is the axis; its right edge is camera -x (x points left, as Mitsuba's).
  expectNear(sensor->generateRay(Vec2(20, 10))->o, Vec3(0, 0, 0.5f), "centre");
  expectNear(sensor->generateRay(Vec2(40, 20))->o, Vec3(-1, -0.5f, 0.5f), "bottom right corner");
}

TEST(OrthographicSensor, ToWorldPlacesAndSizesThePlane) {
  // Mitsuba's documented use: scale the plane, then look from (1, 1, 1) toward (1, 2, 1) with z up.
  // lookat: d = (0, 1, 0), left = up x d = (-1, 0, 0), up' = d x left = (0, 0, 1).
  auto sensor = sensorWith(R"(<transform name="to_world"><scale x="10" y="10"/>
      <lookat origin="1, 1, 1" target="1, 2, 1" up="0, 0, 1"/></transform>)");
  // Camera (0.5, 0.25, 0.01) for film (0.25, 0.25) -> scaled (5, 2.5, 0.01) -> world
  // (1, 1, 1) + 5 (-1, 0, 0) + 2.5 (0, 0, 1) + 0.01 (0, 1, 0).
  std::optional<Ray> ray = sensor->generateRay(Vec2(10, 5));
  ASSERT_TRUE(ray.has_value());
  expectNear(ray->o, Vec3(-4, 1.01f, 3.5f), "origin");
  expectNear(ray->d, Vec3(0, 1, 0), "direction");
  EXPECT_FLOAT_EQ(ray->tmax, 10000.0f - 0.01f);
  EXPECT_FALSE(sensor->needsApertureSample());
}

TEST(OrthographicSensor, BadClipRangesAreErrorsNamingTheLine) {
  try {
    sensorWith(R"(<float name="far_clip" value="0.001"/>)");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("test.xml:1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.001"), std::string::npos) << e.what();
  }
}
