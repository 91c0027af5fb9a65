#include <gtest/gtest.h>

#include "barbule/parameters.h"
#include "shapes/instance_shape.h"
#include "support/error_test_support.h"
#include "support/feather_test_util.h"
#include "support/render_test_support.h"

using namespace columba;
using namespace columba::testing;

namespace {

std::unique_ptr<Scene> sceneWith(const std::string& shapes) {
  ParsedScene parsed =
      loadSceneString("<scene version=\"3.0.0\">" + shapes + "</scene>", "<test>", ".", {}, builtinPlugins());
  return std::make_unique<Scene>(parsed, SourceLocation{"<test>", 0});
}

// The message of the InputError that loading `shapes` throws, "" if none.
std::string loadError(const std::string& shapes) {
  try {
    sceneWith(shapes);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectNear(const Vec3& got, const Vec3& expected, float tolerance) {
  EXPECT_NEAR(got.x, expected.x, tolerance);
  EXPECT_NEAR(got.y, expected.y, tolerance);
  EXPECT_NEAR(got.z, expected.z, tolerance);
}

const char* kUnitSphereGroup = R"(<shape type="shapegroup" id="ball"><shape type="sphere"/></shape>)";

}  // namespace

TEST(Instancing, InstancedSphereIsHitWhereTheTransformedSphereIs) {
  // The unit sphere scaled by 2 and moved to (3, 0, 0).
  auto scene = sceneWith(std::string(kUnitSphereGroup) + R"(
    <shape type="instance"><ref id="ball"/>
      <transform name="to_world"><scale value="2"/><translate x="3"/></transform></shape>)");
  auto top = scene->intersect(Ray{Vec3(3, 0, 10), Vec3(0, 0, -1)});
  ASSERT_TRUE(top.has_value());
  EXPECT_NEAR(top->t, 8.0f, 1e-5f);
  expectNear(top->p, Vec3(3, 0, 2), 1e-5f);
  expectNear(top->ng, Vec3(0, 0, 1), 1e-5f);
  // Off the axis: x = 1 from the centre meets the sphere at z = sqrt(3).
  auto side = scene->intersect(Ray{Vec3(4, 0, 10), Vec3(0, 0, -1)});
  ASSERT_TRUE(side.has_value());
  EXPECT_NEAR(side->t, 10.0f - std::sqrt(3.0f), 1e-5f);
  expectNear(side->p, Vec3(4, 0, std::sqrt(3.0f)), 1e-5f);
  expectNear(side->ng, Vec3(0.5f, 0, std::sqrt(3.0f) / 2), 1e-5f);
  expectNear(side->shading.n, side->ng, 1e-5f);
  // The group by itself is not rendered: nothing at the origin.
  EXPECT_FALSE(scene->intersect(Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)}).has_value());
}

TEST(Instancing, EveryInstanceOfAGroupIsHitAndSharesItsShapes) {
  auto scene = sceneWith(std::string(kUnitSphereGroup) + R"(
    <shape type="instance"><ref id="ball"/><transform name="to_world"><translate x="-5"/></transform></shape>
    <shape type="instance"><ref id="ball"/><transform name="to_world"><translate x="5"/></transform></shape>)");
  auto left = scene->intersect(Ray{Vec3(-5, 0, 10), Vec3(0, 0, -1)});
  auto right = scene->intersect(Ray{Vec3(5, 0, 10), Vec3(0, 0, -1)});
  ASSERT_TRUE(left.has_value());
  ASSERT_TRUE(right.has_value());
  expectNear(left->p, Vec3(-5, 0, 1), 1e-5f);
  expectNear(right->p, Vec3(5, 0, 1), 1e-5f);
  EXPECT_EQ(left->shape, right->shape);
  ASSERT_NE(left->shape->bsdf, nullptr);
  EXPECT_FALSE(scene->intersect(Ray{Vec3(0, 0, 10), Vec3(0, 0, -1)}).has_value());
  EXPECT_EQ(scene->shapeCount(), 2u);
}

TEST(Instancing, ScenesBuiltFromOneParsedSceneEachTraceTheGroup) {
  // Every Scene has its own Embree device; the group's Embree scene is built again for each.
  ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">)" + std::string(kUnitSphereGroup) + R"(
    <shape type="instance"><ref id="ball"/><transform name="to_world"><translate z="-3"/></transform></shape>
    </scene>)",
                                       "<test>", ".", {}, builtinPlugins());
  const Ray ray{Vec3(0, 0, 5), Vec3(0, 0, -1)};
  auto first = std::make_unique<Scene>(parsed, SourceLocation{"<test>", 0});
  Scene second(parsed, SourceLocation{"<test>", 0});
  ASSERT_TRUE(first->intersect(ray).has_value());
  EXPECT_NEAR(first->intersect(ray)->t, 7.0f, 1e-5f);
  first.reset();
  Scene third(parsed, SourceLocation{"<test>", 0});
  for (const Scene* scene : {&second, &third}) {
    auto hit = scene->intersect(ray);
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(hit->t, 7.0f, 1e-5f);
  }
}

TEST(Instancing, AnEmptyGroupRendersNothing) {
  auto scene = sceneWith(R"(<shape type="shapegroup" id="none"/><shape type="instance"><ref id="none"/></shape>
    <shape type="sphere"/>)");
  EXPECT_TRUE(scene->intersect(Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}).has_value());
  EXPECT_FALSE(scene->intersect(Ray{Vec3(3, 0, 5), Vec3(0, 0, -1)}).has_value());
}

TEST(Instancing, RotatedNonUniformlyScaledInstanceTransformsNormals) {
  // The unit sphere scaled by (2, 1, 1) then turned 90 degrees about z: the ellipsoid
  // x^2 + y^2 / 4 + z^2 = 1, whose normal is along (x, y / 4, z).
  auto scene = sceneWith(std::string(kUnitSphereGroup) + R"(
    <shape type="instance"><ref id="ball"/>
      <transform name="to_world"><scale x="2" y="1" z="1"/><rotate z="1" angle="90"/></transform></shape>)");
  const float z = std::sqrt(0.5f);
  auto hit = scene->intersect(Ray{Vec3(0.5f, 1.0f, 10.0f), Vec3(0, 0, -1)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 10.0f - z, 1e-5f);
  expectNear(hit->p, Vec3(0.5f, 1.0f, z), 1e-5f);
  expectNear(hit->ng, normalize(Vec3(0.5f, 0.25f, z)), 1e-5f);
  const Frame& f = hit->shading;
  expectNear(f.n, hit->ng, 1e-5f);
  EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
  EXPECT_NEAR(dot(cross(f.s, f.t), f.n), 1.0f, 1e-5f);
}

TEST(Instancing, InstanceTransformsComposeWithTheGroupShapesOwn) {
  // A rectangle turned 45 degrees about x in the group (the plane z = y), stretched by 2 along y
  // by the instance: the plane z = y / 2, normal along (0, -1/2, 1). A normal mapped as a
  // direction instead would lean along (0, -2, 1).
  auto scene = sceneWith(R"(<shape type="shapegroup" id="tile">
      <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="45"/></transform></shape></shape>
    <shape type="instance"><ref id="tile"/><transform name="to_world"><scale x="1" y="2" z="1"/></transform></shape>)");
  auto hit = scene->intersect(Ray{Vec3(0.2f, 0.4f, 5.0f), Vec3(0, 0, -1)});
  ASSERT_TRUE(hit.has_value());
  expectNear(hit->p, Vec3(0.2f, 0.4f, 0.2f), 1e-5f);
  expectNear(hit->ng, normalize(Vec3(0, -0.5f, 1)), 1e-5f);
  // The shading frame's s follows dp/du, the group's x axis, which the instance leaves alone.
  expectNear(hit->shading.s, Vec3(1, 0, 0), 1e-5f);
}

TEST(Instancing, RotationAboutAnAxisThatIsNotUnitLengthStaysConsistent) {
  // Such a <rotate> also scales and shears; Embree inverts the matrix itself, and the interaction
  // must agree with what Embree traced.
  auto scene = sceneWith(R"(<shape type="shapegroup" id="tile"><shape type="rectangle"/></shape>
    <shape type="instance"><ref id="tile"/>
      <transform name="to_world"><rotate x="1" y="0.5" z="0" angle="30"/><translate z="-1"/></transform></shape>)");
  Transform m = Transform::translate(Vec3(0, 0, -1)) * Transform::rotate(Vec3(1, 0.5f, 0), 30.0f);
  Vec3 edgeX = m.vector(Vec3(1, 0, 0)), edgeY = m.vector(Vec3(0, 1, 0));
  Vec3 expectedNormal = normalize(cross(edgeX, edgeY));
  Ray ray{Vec3(0.1f, 0.2f, 5.0f), normalize(Vec3(0.05f, -0.02f, -1.0f))};
  auto hit = scene->intersect(ray);
  ASSERT_TRUE(hit.has_value());
  expectNear(hit->ng, expectedNormal, 1e-5f);
  expectNear(hit->p, ray.at(hit->t), 1e-5f);
  EXPECT_NEAR(dot(hit->p - m.point(Vec3(0, 0, 0)), expectedNormal), 0.0f, 1e-5f);
}

TEST(Instancing, InstancesMatchTheSameShapesPlacedDirectly) {
  // A cube (a triangle mesh) and a cylinder in one group, placed by a rotation, a non-uniform
  // scale and a translation, against the same shapes with the composed transform as to_world.
  const std::string instance =
      "<rotate x=\"0.6\" y=\"0.8\" z=\"0\" angle=\"30\"/><scale x=\"1.5\" y=\"0.7\" z=\"1.2\"/>"
      "<translate x=\"0.3\" y=\"-0.2\" z=\"0.1\"/>";
  const std::string cube = "<scale value=\"0.4\"/><translate x=\"-0.6\"/>";
  const std::string cylinder = "<rotate y=\"1\" angle=\"80\"/><translate x=\"0.7\" z=\"0.2\"/>";
  auto instanced = sceneWith(
      "<shape type=\"shapegroup\" id=\"g\"><shape type=\"cube\"><transform name=\"to_world\">" + cube +
      "</transform></shape><shape type=\"cylinder\"><float name=\"radius\" value=\"0.3\"/><transform "
      "name=\"to_world\">" +
      cylinder + "</transform></shape></shape><shape type=\"instance\"><ref id=\"g\"/><transform name=\"to_world\">" +
      instance + "</transform></shape>");
  auto direct = sceneWith("<shape type=\"cube\"><transform name=\"to_world\">" + cube + instance +
                          "</transform></shape><shape type=\"cylinder\"><float name=\"radius\" "
                          "value=\"0.3\"/><transform name=\"to_world\">" +
                          cylinder + instance + "</transform></shape>");
  PCG32 rng(11);
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    Vec3 origin = test::randomUnitVector(rng) * 4.0f;
    Vec3 target(2.4f * rng.nextFloat() - 1.2f, 1.6f * rng.nextFloat() - 0.8f, 1.6f * rng.nextFloat() - 0.8f);
    Ray ray{origin, normalize(target - origin)};
    auto a = instanced->intersect(ray);
    auto b = direct->intersect(ray);
    ASSERT_EQ(a.has_value(), b.has_value()) << "ray " << i;
    if (!a) continue;
    ++hits;
    EXPECT_NEAR(a->t, b->t, 1e-4f);
    expectNear(a->p, b->p, 1e-4f);
    expectNear(a->ng, b->ng, 1e-4f);
    expectNear(a->shading.n, b->shading.n, 1e-4f);
    expectNear(a->shading.s, b->shading.s, 1e-4f);
    EXPECT_NEAR(a->uv.x, b->uv.x, 1e-4f);
    EXPECT_NEAR(a->uv.y, b->uv.y, 1e-4f);
    expectNear(a->dpdu, b->dpdu, 1e-3f);
    expectNear(a->dpdv, b->dpdv, 1e-3f);
  }
  EXPECT_GT(hits, 500);
}

TEST(Instancing, InstancedFeatherMatchesTheFeatherPlacedDirectly) {
  // Barb-level feathers are Embree user geometry: Embree hands them the ray in the group's space.
  const Transform own = Transform::scale(Vec3(0.1f, 0.1f, 0.1f));
  const Transform placement =
      Transform::translate(Vec3(0.08f, -0.02f, 0.01f)) * Transform::rotate(normalize(Vec3(1, 2, 0.5f)), 35.0f);
  FeatherShapeParams inGroup, direct;
  inGroup.toWorld = own;
  direct.toWorld = placement * own;
  auto group = std::make_shared<ShapeGroup>(std::vector<std::shared_ptr<Shape>>{
      std::make_shared<FeatherShape>(test::syntheticBarbs(3, 1.2f, 0.6f, 0.12f), inGroup)});
  auto reference = std::make_shared<FeatherShape>(test::syntheticBarbs(3, 1.2f, 0.6f, 0.12f), direct);
  ParsedScene instancedParsed, directParsed;
  instancedParsed.objects = {std::make_shared<InstanceShape>(group, placement)};
  directParsed.objects = {reference};
  Scene instanced(instancedParsed, SourceLocation{"<test>", 0});
  Scene placed(directParsed, SourceLocation{"<test>", 0});

  PCG32 rng(5);
  int hits = 0, mismatches = 0;
  const int rays = 2000;
  for (int i = 0; i < rays; ++i) {
    BarbStrip s = reference->strip(rng.nextUInt() % reference->primitiveCount());
    Vec3 target =
        s.point(rng.nextFloat(), 0.8f * (2.0f * rng.nextFloat() - 1.0f) * std::asin(s.halfWidthStart / s.radius));
    Vec3 toSource = test::randomUnitVector(rng);
    Ray ray{target + toSource * 0.05f, -toSource};
    auto a = instanced.intersect(ray);
    auto b = placed.intersect(ray);
    // Rays grazing a strip's edge may go either way under float round-off; nothing else may differ.
    if (a.has_value() != b.has_value() || (a && std::abs(a->t - b->t) > 1e-5f)) {
      ++mismatches;
      continue;
    }
    if (!a) continue;
    ++hits;
    expectNear(a->p, b->p, 1e-5f);
    // The angle around the thin strip (radius ~1e-3) amplifies round-off by 1 / cos(incidence),
    // and the ramus tilt of mu changes by up to ~20 per radian of it.
    if (std::abs(dot(ray.d, b->ng)) < 0.2f) continue;
    expectNear(a->ng, b->ng, 1e-4f);
    expectNear(a->shading.s, b->shading.s, 1e-4f);
    expectNear(a->shading.t, b->shading.t, 1e-4f);
    EXPECT_NEAR(a->uv.y, b->uv.y, 1e-4f);
    EXPECT_NEAR(test::attribute(*a, "mu"), test::attribute(*b, "mu"), 1e-3f);
  }
  EXPECT_GT(hits, rays / 2);
  EXPECT_LE(mismatches, rays / 500) << mismatches << " of " << rays;
}

TEST(Instancing, InstancesCastShadows) {
  // A plate lit by a directional light from 45 degrees; a square above it, outside the camera's
  // view, either shadows the viewed spot or, moved aside, does not.
  auto render = [](const std::string& placement) {
    std::string xml = plateUnderDirectionalLight(R"(<spectrum name="irradiance" value="3"/>)", 0.5f, 4);
    const std::string light = R"(<vector name="direction" x="0" y="0" z="-1"/>)";
    xml.replace(xml.find(light), light.size(), R"(<vector name="direction" x="-1" y="0" z="-1"/>)");
    const std::string occluder = R"(<shape type="shapegroup" id="square">
        <shape type="rectangle"><transform name="to_world"><scale value="0.5"/></transform></shape></shape>
      <shape type="instance"><ref id="square"/><transform name="to_world">)" +
                                 placement + "</transform></shape></scene>";
    xml.replace(xml.rfind("</scene>"), 8, occluder);
    return meanColour(renderSceneString(xml), 0, 0, 8, 8);
  };
  Vec3 shadowed = render(R"(<translate x="1" z="1"/>)");
  Vec3 lit = render(R"(<translate x="-1" z="1"/>)");
  EXPECT_EQ(shadowed.y, 0.0f);
  EXPECT_GT(lit.y, 0.1f);
}

TEST(Instancing, InstancedSceneRendersAsTheSceneWrittenOut) {
  // A floor, two spheres and a cube under an area light, through instances of two groups, and
  // written out shape by shape with each composed transform.
  auto scene = [](const std::string& shapes) {
    return R"(<scene version="3.0.0"><integrator type="path"><integer name="max_depth" value="4"/></integrator>
      <sensor type="perspective"><float name="fov" value="50"/>
        <transform name="to_world"><lookat origin="0, 3, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
        <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="24"/></film>
        <sampler type="independent"><integer name="sample_count" value="8"/></sampler></sensor>
      <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="90"/><translate y="3"/></transform>
        <emitter type="area"><spectrum name="radiance" value="5"/></emitter></shape>)" +
           shapes + "</scene>";
  };
  const std::string floor = R"(<rotate x="1" angle="-90"/>)";
  const std::string floorPlacement = R"(<scale value="3"/><translate y="-0.5"/>)";
  const std::string cube = R"(<scale value="0.3"/><translate x="0.5" y="-0.2"/>)";
  const std::string left = R"(<rotate y="1" angle="40"/><translate x="-1"/>)";
  const std::string right = R"(<scale x="1" y="1.5" z="1"/><translate x="1" z="-0.5"/>)";
  auto transform = [](const std::string& steps) { return R"(<transform name="to_world">)" + steps + "</transform>"; };
  auto sphere = [](const std::string& contents) {
    return R"(<shape type="sphere"><float name="radius" value="0.4"/>)" + contents + "</shape>";
  };
  auto diffuse = R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.7, 0.3, 0.2"/></bsdf>)";
  const std::string instanced = R"(<shape type="shapegroup" id="floor"><shape type="rectangle">)" + transform(floor) +
                                R"(</shape></shape><shape type="shapegroup" id="pair">)" +
                                sphere(std::string(diffuse)) + R"(<shape type="cube">)" + transform(cube) +
                                R"(</shape></shape>
      <shape type="instance"><ref id="floor"/>)" +
                                transform(floorPlacement) + R"(</shape>
      <shape type="instance"><ref id="pair"/>)" +
                                transform(left) + R"(</shape>
      <shape type="instance"><ref id="pair"/>)" +
                                transform(right) + "</shape>";
  // A sphere's own radius comes first, then the instance's transform.
  const std::string written = R"(<shape type="rectangle">)" + transform(floor + floorPlacement) + "</shape>" +
                              sphere(diffuse + transform(left)) + R"(<shape type="cube">)" + transform(cube + left) +
                              "</shape>" + sphere(diffuse + transform(right)) + R"(<shape type="cube">)" +
                              transform(cube + right) + "</shape>";
  Image a = renderSceneString(scene(instanced));
  Image b = renderSceneString(scene(written));
  ASSERT_EQ(a.rgb.size(), b.rgb.size());
  double sumA = 0, sumB = 0, worst = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) {
    sumA += a.rgb[i];
    sumB += b.rgb[i];
    worst = std::max(worst, double(std::abs(a.rgb[i] - b.rgb[i])));
  }
  EXPECT_GT(sumB, 0.0);
  // The two differ only by float round-off in the hits (1.3e-7 at most when written).
  EXPECT_NEAR(sumA, sumB, 1e-6 * sumB);
  EXPECT_LT(worst, 1e-5) << "largest difference of a pixel's channel";
}

TEST(Instancing, RefusesEmittersInAGroup) {
  expectContains(loadError(R"(<shape type="shapegroup" id="g">
      <shape type="sphere"><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape></shape>)"),
                 {"<test>:2", "area emitter", "shapegroup"});
  expectContains(loadError(R"(<shape type="shapegroup" id="g"><shape type="sphere"/>
      <emitter type="point"/></shape>)"),
                 {"<test>:2", "emitters", "shapegroup"});
}

TEST(Instancing, RefusesNestedGroupsAndInstances) {
  expectContains(loadError(R"(<shape type="shapegroup" id="outer">
      <shape type="shapegroup" id="inner"><shape type="sphere"/></shape></shape>)"),
                 {"<test>:2", "cannot contain another shapegroup"});
  expectContains(loadError(R"(<shape type="shapegroup" id="a"><shape type="sphere"/></shape>
    <shape type="shapegroup" id="b">
      <shape type="instance"><ref id="a"/></shape></shape>)"),
                 {"<test>:3", "cannot contain an instance"});
}

TEST(Instancing, AnInstanceNeedsExactlyOneGroup) {
  expectContains(loadError(R"(
    <shape type="instance"><transform name="to_world"><translate x="1"/></transform></shape>)"),
                 {"<test>:2", "exactly one shapegroup", "not 0"});
  expectContains(loadError(std::string(kUnitSphereGroup) + R"(
    <shape type="instance"><ref id="ball"/><ref id="ball"/></shape>)"),
                 {"<test>:2", "exactly one shapegroup", "not 2"});
  expectContains(loadError(R"(<shape type="sphere" id="s"/>
    <shape type="instance"><ref id="s"/></shape>)"),
                 {"<test>:2", "exactly one shapegroup"});
  expectContains(loadError(R"(
    <shape type="instance"><ref id="nowhere"/></shape>)"),
                 {"<test>:2", "unknown id 'nowhere'"});
}

// Embree inverts an instance's matrix in single precision and aborts on rays beyond its range in
// the group's space: a scale of 1e-20 (and already 1e-16, whose determinant is 0 as a float)
// aborted the render.
TEST(Instancing, TransformsEmbreeCannotTraceThroughAreRefusedNamingTheLine) {
  auto instance = [](const std::string& steps) {
    return std::string(kUnitSphereGroup) +
           "\n<shape type=\"instance\"><ref id=\"ball\"/>\n<transform name=\"to_world\">" + steps +
           "</transform></shape>";
  };
  for (const char* steps :
       {R"(<scale value="1e-20"/>)", R"(<scale value="1e-16"/>)", R"(<scale z="1e-40"/>)", R"(<scale value="1e13"/>)"})
    expectContains(loadError(instance(steps)), {"<test>:3", "'instance'", "to_world", "determinant"});
  expectContains(loadError(instance(R"(<scale value="3e-13"/>)")), {"<test>:3", "to_world", "beyond"});
  expectContains(loadError(instance(R"(<translate x="1e19"/>)")), {"<test>:3", "to_world", "beyond"});
  // Small but traceable: hit where the scaled sphere is.
  auto scene = sceneWith(instance(R"(<scale value="1e-12"/>)"));
  auto hit = scene->intersect(Ray{Vec3(0, 0, 1), Vec3(0, 0, -1)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
}

TEST(Instancing, AnInstanceGivesItsBarbuleValuesInPlaceOfItsShapesOwn) {
  // A sphere instanced twice: one copy as it is, one giving barbule values.
  const std::string group = R"(<shape type="shapegroup" id="f"><shape type="sphere"/></shape>)";
  auto scene = sceneWith(group + R"(
    <shape type="instance"><ref id="f"/><transform name="to_world"><translate x="-3"/></transform></shape>
    <shape type="instance"><ref id="f"/><float name="height" value="0.51"/><float name="H" value="1.4"/>
      <float name="mu" value="-0.2"/><transform name="to_world"><translate x="3"/></transform></shape>)");
  auto plain = scene->intersect(Ray{Vec3(-3, 0, 10), Vec3(0, 0, -1)});
  auto given = scene->intersect(Ray{Vec3(3, 0, 10), Vec3(0, 0, -1)});
  ASSERT_TRUE(plain && given);
  EXPECT_TRUE(plain->attributes.empty());
  EXPECT_FLOAT_EQ(test::attribute(*given, "height"), 0.51f);
  EXPECT_FLOAT_EQ(test::attribute(*given, "H"), 1.4f);
  EXPECT_FLOAT_EQ(test::attribute(*given, "mu"), -0.2f);
  // Over a feather's own per-vertex values too.
  FeatherShapeParams params;
  auto feather = std::make_shared<FeatherShape>(test::syntheticBarbs(3, 1.2f, 0.6f, 0.12f), params);
  SurfaceAttributes thickness;
  thickness.set(kCortexThicknessAttribute, 0.42f);
  ParsedScene parsed;
  parsed.objects = {std::make_shared<InstanceShape>(
      std::make_shared<ShapeGroup>(std::vector<std::shared_ptr<Shape>>{feather}), Transform(), thickness)};
  Scene featherScene(parsed, SourceLocation{"<test>", 0});
  BarbStrip s = feather->strip(0);
  Vec3 target = s.point(0.5f, 0.0f);
  auto hit = featherScene.intersect(Ray{target + s.n * 0.05f, -s.n});
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(test::attribute(*hit, "height"), 0.42f);
  EXPECT_TRUE(hit->attributes.find(kBarbuleSpacingAttribute).has_value());  // the feather's own, kept
}

TEST(Instancing, BarbuleValuesOutOfRangeAreRefused) {
  const std::string group = R"(<shape type="shapegroup" id="f"><shape type="sphere"/></shape>)";
  EXPECT_NE(loadError(group + R"(<shape type="instance"><ref id="f"/><float name="height" value="-0.1"/></shape>)")
                .find("parameter 'height': must be a finite number of at least 0, not -0.1"),
            std::string::npos);
  EXPECT_NE(loadError(group + R"(<shape type="instance"><ref id="f"/><float name="H" value="0"/></shape>)")
                .find("parameter 'H': must be a finite number above 0, not 0"),
            std::string::npos);
}
