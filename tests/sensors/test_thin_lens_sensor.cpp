// The thin-lens camera: every ray of a film point passes through the point of the focal plane
// that the pinhole camera sees there, so that plane is sharp, and at another depth z the rays of
// one film point spread over the circle of confusion of radius R |z - f| / f (lens radius R,
// focus distance f). The perspective camera draws no aperture sample.
#include <gtest/gtest.h>

#include <cmath>

#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "sensors/thin_lens_sensor.h"

using namespace columba;

namespace {

// A 64 x 48 sensor of `type` with the given parameters, looking along +z from the origin.
template <typename SensorType>
std::shared_ptr<SensorType> sensorWith(const std::string& type, const std::string& parameters) {
  const std::string xml = "<scene version=\"3.0.0\"><sensor type=\"" + type + "\">" + parameters +
                          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"64\"/>"
                          "<integer name=\"height\" value=\"48\"/></film></sensor></scene>";
  ParsedScene scene = loadSceneString(xml, "lens.xml", "", {}, builtinPlugins());
  auto sensor = std::dynamic_pointer_cast<SensorType>(scene.objects.at(0));
  if (!sensor) throw std::logic_error("not a " + type + " sensor");
  return sensor;
}

const char* kView = R"(<float name="fov" value="40"/><float name="focus_distance" value="5"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>)";

// Where a ray reaches the plane z (camera space is world space here).
Vec3 atDepth(const Ray& ray, float z) { return ray.o + ray.d * ((z - ray.o.z) / ray.d.z); }

std::string errorOf(const std::string& parameters) {
  try {
    sensorWith<ThinLensSensor>("thinlens", parameters);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ThinLensSensor, TheFocalPlaneIsSharpAndOtherDepthsBlurByTheCircleOfConfusion) {
  const float R = 0.2f, f = 5.0f;
  auto lens =
      sensorWith<ThinLensSensor>("thinlens", std::string(kView) + R"(<float name="aperture_radius" value="0.2"/>)");
  auto pinhole = sensorWith<PerspectiveSensor>("perspective", kView);
  EXPECT_TRUE(lens->needsApertureSample());
  EXPECT_FALSE(pinhole->needsApertureSample());
  for (Vec2 film : {Vec2(32, 24), Vec2(3.5f, 40.25f), Vec2(60, 2)}) {
    const Ray chief = *pinhole->generateRay(film);
    const Vec3 focus = atDepth(chief, f);
    float largest = 0.0f;
    for (int i = 0; i < 16; ++i)
      for (int j = 0; j < 16; ++j) {
        const Ray ray = *lens->generateRay(film, Vec2((i + 0.5f) / 16, (j + 0.5f) / 16));
        // The ray leaves the lens disk (z = 0) ...
        const Vec3 onLens = atDepth(ray, 0.0f);
        const float r = std::hypot(onLens.x, onLens.y);
        EXPECT_LE(r, R * 1.0001f);
        largest = std::max(largest, r);
        // ... and passes through the pinhole's point of the focal plane.
        const Vec3 p = atDepth(ray, f);
        EXPECT_NEAR(p.x, focus.x, 1e-5f);
        EXPECT_NEAR(p.y, focus.y, 1e-5f);
        // At depth z its distance from the chief ray's point there is r |z - f| / f.
        for (float z : {2.5f, 10.0f, 20.0f}) {
          const Vec3 q = atDepth(ray, z), c = atDepth(chief, z);
          EXPECT_NEAR(std::hypot(q.x - c.x, q.y - c.y), r * std::abs(z - f) / f, 2e-5f * z) << "z = " << z;
        }
        // Its clip range starts at the near plane: tmin along the ray is near_clip / cos.
        EXPECT_NEAR(ray.tmin, 0.01f / ray.d.z, 1e-6f);
      }
    // The samples cover the lens out to its rim (the outermost cells' centres, 15/16 of R).
    EXPECT_GT(largest, R * 15.0f / 16.0f * 0.999f);
  }
}

TEST(ThinLensSensor, AMissingApertureOrAScalingTransformIsAnError) {
  EXPECT_NE(errorOf(kView).find("aperture_radius"), std::string::npos);
  const std::string scaled = R"(<float name="aperture_radius" value="0.1"/>
      <transform name="to_world"><scale value="2"/></transform>)";
  EXPECT_NE(errorOf(scaled).find("must not scale"), std::string::npos) << errorOf(scaled);
  EXPECT_NE(errorOf(R"(<float name="aperture_radius" value="-1"/>)").find("not -1"), std::string::npos);
}

TEST(PerspectiveSensor, FocusDistanceIsAcceptedAndChangesNothing) {
  auto plain = sensorWith<PerspectiveSensor>("perspective", R"(<float name="fov" value="40"/>)");
  auto focused = sensorWith<PerspectiveSensor>(
      "perspective", R"(<float name="fov" value="40"/><float name="focus_distance" value="3"/>)");
  const Ray a = *plain->generateRay(Vec2(5, 7)), b = *focused->generateRay(Vec2(5, 7), Vec2(0.9f, 0.1f));
  EXPECT_EQ(a.d, b.d);
  EXPECT_EQ(a.o, b.o);
}
