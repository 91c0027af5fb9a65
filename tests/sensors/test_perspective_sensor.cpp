// The perspective camera's field of view as Mitsuba reads it: `fov` along `fov_axis`, or
// without it a lens of `focal_length` (50mm by default) on 36 x 24 mm film, on the diagonal.
#include <gtest/gtest.h>

#include <cmath>
#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "sensors/perspective_sensor.h"

using namespace columba;

namespace {

// A 400 x 300 (4:3) perspective sensor with the given parameters.
std::shared_ptr<PerspectiveSensor> sensorWith(const std::string& parameters) {
  const std::string xml = "<scene version=\"3.0.0\"><sensor type=\"perspective\">" + parameters +
                          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"400\"/>"
                          "<integer name=\"height\" value=\"300\"/></film></sensor></scene>";
  ParsedScene scene = loadSceneString(xml, "test.xml", "", {}, builtinPlugins());
  auto sensor = std::dynamic_pointer_cast<PerspectiveSensor>(scene.objects.at(0));
  if (!sensor) throw std::logic_error("not a perspective sensor");
  return sensor;
}

double degrees(double radians) { return radians * 180.0 / 3.14159265358979323846; }

}  // namespace

TEST(PerspectiveSensor, DefaultFieldOfViewIsAFiftyMillimetreLensOnTheDiagonal) {
  // By hand: the 36 x 24 mm diagonal, 43.267 mm, seen from 50 mm: 2 atan(21.633 / 50) = 46.79
  // degrees; on a 4:3 image the half-diagonal's tangent splits as 4/5 along x and 3/5 along y.
  const double tanHalfDiagonal = std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / 2.0 / 50.0;
  EXPECT_NEAR(degrees(2.0 * std::atan(tanHalfDiagonal)), 46.793, 1e-3);
  auto sensor = sensorWith("");
  EXPECT_NEAR(sensor->tanHalfFovX(), tanHalfDiagonal * 0.8, 1e-6);
  EXPECT_NEAR(sensor->tanHalfFovY(), tanHalfDiagonal * 0.6, 1e-6);
  EXPECT_NEAR(degrees(2.0 * std::atan(sensor->tanHalfFovX())), 38.18, 0.01);  // not 39.3 on x
}

TEST(PerspectiveSensor, FocalLengthAsMitsubaWritesIt) {
  const double tanHalfDiagonal35 = std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / 2.0 / 35.0;
  for (const char* given :
       {"<string name=\"focal_length\" value=\"35mm\"/>", "<string name=\"focal_length\" value=\"35\"/>",
        "<float name=\"focal_length\" value=\"35\"/>"})
    EXPECT_NEAR(sensorWith(given)->tanHalfFovX(), tanHalfDiagonal35 * 0.8, 1e-6) << given;
  EXPECT_THROW(sensorWith("<string name=\"focal_length\" value=\"35 mm wide\"/>"), InputError);
  EXPECT_THROW(sensorWith("<float name=\"focal_length\" value=\"-5\"/>"), InputError);
  EXPECT_THROW(sensorWith("<float name=\"fov\" value=\"40\"/><string name=\"focal_length\" value=\"35mm\"/>"),
               InputError);
}

TEST(PerspectiveSensor, ExplicitFovIsAlongXByDefault) {
  auto sensor = sensorWith("<float name=\"fov\" value=\"40\"/>");
  EXPECT_NEAR(sensor->tanHalfFovX(), std::tan(20.0 * 3.14159265358979323846 / 180.0), 1e-6);
  EXPECT_NEAR(sensor->tanHalfFovY(), sensor->tanHalfFovX() * 0.75, 1e-6);
}
