#include <gtest/gtest.h>

#include <typeinfo>

#include "builtin/builtin_plugins.h"
#include "core/rng.h"
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

TEST(Shapes, AFewAnalyticShapesTestedInTurnHitWhatEmbreeHits) {
  // Up to four analytic shapes are intersected in turn; a fifth (far away, never hit) makes the
  // scene go through Embree. Both must find the same nearest hit, bit for bit, for rays among and
  // through overlapping shapes, from inside the sphere and the cylinder too.
  const std::string shapes = R"(
    <shape type="sphere"><point name="center" x="0" y="0" z="0"/><float name="radius" value="1"/></shape>
    <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="30"/><scale value="1.5"/></transform></shape>
    <shape type="disk"><transform name="to_world"><rotate y="1" angle="70"/><translate x="0.3"/></transform></shape>
    <shape type="cylinder"><point name="p0" x="-1" y="-0.5" z="-1"/><point name="p1" x="1" y="0.5" z="1"/>
      <float name="radius" value="0.4"/></shape>)";
  auto inTurn = sceneWith(shapes);
  auto throughEmbree = sceneWith(shapes + R"(<shape type="sphere"><point name="center" x="100" y="0" z="0"/></shape>)");
  PCG32 rng(8);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    Vec3 o(4.0f * rng.nextFloat() - 2.0f, 4.0f * rng.nextFloat() - 2.0f, 4.0f * rng.nextFloat() - 2.0f);
    Vec3 target(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f);
    Ray ray{o, target - o};
    ray.tmin = i % 2 ? 1e-3f : 0.0f;
    ray.tmax = i % 3 ? 10.0f : 0.7f;
    auto a = inTurn->intersect(ray), b = throughEmbree->intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value()) << i;
    if (!a) continue;
    ++hits;
    ASSERT_EQ(a->t, b->t) << i;
    ASSERT_EQ(typeid(*a->shape), typeid(*b->shape)) << i;
    ASSERT_EQ(a->p.x, b->p.x) << i;
    ASSERT_EQ(a->ng.z, b->ng.z) << i;
  }
  EXPECT_GT(hits, 10000);
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

TEST(Shapes, CylinderIsMitsubasOpenTubeAroundP0P1) {
  // Radius 0.5 around the segment (1, 2, 3) -> (1, 2, 5): the local frame of the axis +z has s = +x.
  auto scene = sceneWith(R"(
    <shape type="cylinder"><point name="p0" x="1" y="2" z="3"/><point name="p1" x="1" y="2" z="5"/>
      <float name="radius" value="0.5"/></shape>)");
  auto hit = scene->intersect(Ray{Vec3(5, 2, 4.5f), Vec3(-1, 0, 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 3.5f, 1e-5f);
  EXPECT_NEAR(hit->ng.x, 1.0f, 1e-6f);
  EXPECT_NEAR(hit->uv.x, 0.0f, 1e-6f);         // angle 0
  EXPECT_NEAR(hit->uv.y, 0.75f, 1e-6f);        // 1.5 of the length 2
  EXPECT_NEAR(hit->shading.s.y, 1.0f, 1e-5f);  // dp/du turns counter-clockwise about the axis
  // From the axis, the far wall is hit from inside (the normal still points outward); past the
  // ends and along the axis there is nothing (no end caps).
  auto inside = scene->intersect(Ray{Vec3(1, 2, 4), Vec3(0, 1, 0)});
  ASSERT_TRUE(inside.has_value());
  EXPECT_NEAR(inside->t, 0.5f, 1e-5f);
  EXPECT_NEAR(inside->ng.y, 1.0f, 1e-6f);
  EXPECT_NEAR(inside->uv.x, 0.25f, 1e-6f);
  EXPECT_FALSE(scene->intersect(Ray{Vec3(5, 2, 5.01f), Vec3(-1, 0, 0)}).has_value());
  EXPECT_FALSE(scene->intersect(Ray{Vec3(1, 2, 0), Vec3(0, 0, 1)}).has_value());
  // A ray entering through the open end hits the inside of the wall.
  auto throughEnd = scene->intersect(Ray{Vec3(1, 2, 6), normalize(Vec3(0, 0.5f, -1))});
  ASSERT_TRUE(throughEnd.has_value());
  EXPECT_NEAR(throughEnd->p.z, 5.0f, 1e-4f);
}

TEST(Shapes, CylinderAreaAndSamplingAndItsLimits) {
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
    <shape type="cylinder"><float name="radius" value="0.5"/><point name="p1" x="0" y="2" z="0"/>
      <transform name="to_world"><scale value="3"/></transform>
      <emitter type="area"><rgb name="radiance" value="1"/></emitter></shape></scene>)",
                                       "<test>", ".", {}, builtinPlugins());
  auto tube = std::dynamic_pointer_cast<Shape>(parsed.objects.at(0));
  EXPECT_NEAR(tube->surfaceArea(), kTwoPi * 1.5f * 6.0f, 1e-3f);
  for (Vec2 u : {Vec2(0.1f, 0.2f), Vec2(0.9f, 0.7f)}) {
    PositionSample ps = tube->samplePosition(u, false);
    EXPECT_NEAR(std::sqrt(ps.p.x * ps.p.x + ps.p.z * ps.p.z), 1.5f, 1e-5f);  // on the tube around y
    EXPECT_NEAR(ps.p.y, 6.0f * u.x, 1e-5f);
    EXPECT_NEAR(dot(ps.n, Vec3(ps.p.x, 0, ps.p.z) / 1.5f), 1.0f, 1e-5f);
    EXPECT_NEAR(ps.pdfArea, 1.0f / tube->surfaceArea(), 1e-7f);
  }
  auto load = [](const std::string& params) {
    loadSceneString("<scene version=\"3.0.0\">\n<shape type=\"cylinder\">\n" + params + "</shape></scene>", "s.xml",
                    ".", {}, builtinPlugins());
  };
  EXPECT_THROW(load("<float name=\"radius\" value=\"0\"/>"), InputError);
  EXPECT_THROW(load("<point name=\"p1\" x=\"0\" y=\"0\" z=\"0\"/>"), InputError);
  try {
    load(R"(<transform name="to_world"><scale x="2" y="1" z="1"/></transform>
            <emitter type="area"><rgb name="radiance" value="1"/></emitter>)");
    ADD_FAILURE() << "an emitting elliptic tube was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("keeps it round"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("s.xml:"), std::string::npos) << e.what();
  }
}
