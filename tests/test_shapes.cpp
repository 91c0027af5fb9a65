#include <gtest/gtest.h>

#include "builtin/builtin_plugins.h"
#include "scene/scene.h"

using namespace columba;

namespace {
std::unique_ptr<Scene> sceneWith(const std::string& shapes) {
  ParsedScene parsed =
      loadSceneString("<scene version=\"3.0.0\">" + shapes + "</scene>", "<test>", ".", {}, builtinPlugins());
  return std::make_unique<Scene>(parsed, SourceLocation{"<test>", 0});
}
}  // namespace

TEST(Shapes, RectangleShadingFrameFollowsTheUDirection) {
  // As in Mitsuba, local x (s) is dp/du: the rectangle's x axis, here rotated by 30 degrees.
  auto scene =
      sceneWith(R"(<shape type="rectangle"><transform name="to_world"><rotate z="1" angle="30"/></transform></shape>)");
  auto hit = scene->intersect(Ray{Vec3(0.1f, 0.2f, 1.0f), Vec3(0, 0, -1)});
  ASSERT_TRUE(hit.has_value());
  Vec3 expected(std::cos(degToRad(30.0f)), std::sin(degToRad(30.0f)), 0.0f);
  EXPECT_NEAR(dot(hit->shading.s, expected), 1.0f, 1e-5f);
  EXPECT_NEAR(hit->shading.n.z, 1.0f, 1e-6f);
  EXPECT_NEAR(dot(cross(hit->shading.s, hit->shading.t), hit->shading.n), 1.0f, 1e-5f);
}

TEST(Shapes, AnalyticShapesHitWhereExpected) {
  auto scene = sceneWith(R"(
    <shape type="sphere"><point name="center" x="0" y="0" z="5"/><float name="radius" value="2"/></shape>
    <shape type="disk"><transform name="to_world"><scale x="3" y="1" z="1"/><translate x="10"/></transform></shape>)");
  auto sphereHit = scene->intersect(Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)});
  ASSERT_TRUE(sphereHit.has_value());
  EXPECT_NEAR(sphereHit->t, 3.0f, 1e-5f);
  EXPECT_NEAR(sphereHit->ng.z, -1.0f, 1e-5f);
  // The elliptical disk reaches 3 along x but only 1 along y.
  EXPECT_TRUE(scene->intersect(Ray{Vec3(12.9f, 0, 1), Vec3(0, 0, -1)}).has_value());
  EXPECT_FALSE(scene->intersect(Ray{Vec3(10, 1.1f, 1), Vec3(0, 0, -1)}).has_value());
}

TEST(Shapes, SurfaceAreasFollowTheirTransforms) {
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
    <shape type="disk"><transform name="to_world"><scale x="3" y="2" z="1"/></transform></shape>
    <shape type="rectangle"><transform name="to_world"><scale x="2" y="0.5" z="1"/><rotate x="1" angle="40"/></transform></shape>
    <shape type="sphere"><float name="radius" value="0.5"/></shape>
    <shape type="cube"><transform name="to_world"><scale value="2"/></transform></shape></scene>)",
                                       "<test>", ".", {}, builtinPlugins());
  std::vector<float> areas;
  for (const auto& object : parsed.objects) areas.push_back(std::dynamic_pointer_cast<Shape>(object)->surfaceArea());
  ASSERT_EQ(areas.size(), 4u);
  EXPECT_NEAR(areas[0], kPi * 3.0f * 2.0f, 1e-4f);
  EXPECT_NEAR(areas[1], 4.0f * 1.0f, 1e-5f);
  EXPECT_NEAR(areas[2], 4.0f * kPi * 0.25f, 1e-5f);
  EXPECT_NEAR(areas[3], 6.0f * 16.0f, 1e-3f);
}
