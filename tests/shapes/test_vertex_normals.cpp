#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "builtin/builtin_plugins.h"
#include "core/warning_listener.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "shapes/vertex_normals.h"
#include "support/temp_dir_test.h"

using namespace columba;

namespace {

void expectNear(const Vec3& actual, const Vec3& expected, float tolerance = 1e-6f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// Two right triangles hinged along the y axis: one in the z = 0 plane (normal +z, a right angle
// at the origin), one in the x = 0 plane (normal +x, 45 degrees at the origin).
const std::vector<Vec3> kHingePositions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 1}};
const std::vector<uint32_t> kHingeIndices = {0, 1, 2, 0, 2, 3};

// Plain per-face averages, by count or by area, would give (1, 0, 1) / sqrt(2) at the origin.
TEST(VertexNormals, EachFaceCountsWithItsAngleAtTheVertex) {
  std::vector<Vec3> n = angleWeightedVertexNormals(kHingePositions, kHingeIndices);
  ASSERT_EQ(n.size(), 4u);
  // Origin: +z with weight pi/2, +x with weight pi/4.
  expectNear(n[0], Vec3(1, 0, 2) / std::sqrt(5.0f));
  expectNear(n[1], Vec3(0, 0, 1));
  // (0, 1, 0): +z with weight pi/4, +x with weight pi/2.
  expectNear(n[2], Vec3(2, 0, 1) / std::sqrt(5.0f));
  expectNear(n[3], Vec3(1, 0, 0));
}

TEST(VertexNormals, HowAFaceIsSplitDoesNotTiltTheNormal) {
  // Three unit squares meeting at the origin's corner of a cube. The z = 0 square is split by
  // the diagonal through the origin (two triangles there), the others by the other diagonal
  // (one triangle there); by angle each square weighs pi/2, so the normal is the diagonal.
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {1, 0, 1}};
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 2, 3,   // z = 0, normal +z
                                         0, 3, 5, 3, 4, 5,   // x = 0, normal +x
                                         0, 5, 1, 5, 6, 1};  // y = 0, normal +y
  std::vector<Vec3> n = angleWeightedVertexNormals(p, indices);
  expectNear(n[0], Vec3(1, 1, 1) / std::sqrt(3.0f));
}

TEST(VertexNormals, DegenerateTrianglesAddNothing) {
  std::vector<Vec3> p = kHingePositions;
  p.push_back({2, 0, 0});  // on the line through vertices 0 and 1
  std::vector<uint32_t> indices = kHingeIndices;
  indices.insert(indices.end(), {0, 1, 4, 4, 4, 4});
  std::vector<Vec3> n = angleWeightedVertexNormals(p, indices);
  expectNear(n[0], Vec3(1, 0, 2) / std::sqrt(5.0f));
  expectNear(n[1], Vec3(0, 0, 1));
  expectNear(n[4], Vec3(0, 0, 0));  // only in degenerate triangles: no normal
}

class MeshWithoutNormals : public columba::testing::TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    write("hinge.ply",
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
          "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
          "0 0 0\n1 0 0\n0 1 0\n0 1 1\n3 0 1 2\n3 0 2 3\n");
    write("hinge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 1\nf 1 2 3\nf 1 3 4\n");
  }
  // The first surface a ray straight down through (0.25, 0.25) meets: the hinge's z = 0 face.
  SurfaceInteraction hitFromAbove(const std::string& shape) {
    ParsedScene parsed = loadSceneString("<scene version='3.0.0'>" + shape + "</scene>", "scene.xml", dir_.string(), {},
                                         builtinPlugins());
    Scene scene(parsed, SourceLocation{"scene.xml", 0});
    auto hit = scene.intersect(Ray{Vec3(0.25f, 0.25f, 1.0f), Vec3(0, 0, -1)});
    EXPECT_TRUE(hit.has_value());
    return hit.value_or(SurfaceInteraction{});
  }
};

// The hinge stretched to twice its height: its x = 0 face then has angle atan(2) at the origin
// and still a right angle at (0, 1, 0), so the normals are made from the world-space mesh
// (Mitsuba's order); transforming object-space normals would give other ones.
TEST_F(MeshWithoutNormals, ShadingInterpolatesSmoothNormalsOfTheWorldSpaceMesh) {
  const Vec3 n0 = normalize(Vec3(std::atan(2.0f), 0, kHalfPi));
  const Vec3 n1(0, 0, 1);
  const Vec3 n2 = normalize(Vec3(kHalfPi, 0, kHalfPi / 2));
  // (0.25, 0.25, 0) has barycentric weights 0.5, 0.25, 0.25 on vertices 0, 1, 2.
  const Vec3 expected = normalize(n0 * 0.5f + n1 * 0.25f + n2 * 0.25f);
  const std::string scale = "<transform name='to_world'><scale x='1' y='1' z='2'/></transform>";
  for (const char* type : {"ply", "obj"}) {
    SCOPED_TRACE(type);
    SurfaceInteraction si = hitFromAbove(std::string("<shape type='") + type +
                                         "'><string name='filename' value='hinge." + type + "'/>" + scale + "</shape>");
    expectNear(si.ng, Vec3(0, 0, 1));
    expectNear(si.shading.n, expected, 1e-5f);
    EXPECT_NEAR(dot(si.shading.s, si.shading.n), 0.0f, 1e-5f);
  }
}

TEST_F(MeshWithoutNormals, FaceNormalsKeepsTheFacets) {
  for (const char* type : {"ply", "obj"}) {
    SCOPED_TRACE(type);
    SurfaceInteraction si =
        hitFromAbove(std::string("<shape type='") + type + "'><string name='filename' value='hinge." + type +
                     "'/><boolean name='face_normals' value='true'/></shape>");
    expectNear(si.shading.n, Vec3(0, 0, 1));
  }
}

// A latitude-longitude unit sphere as OBJ text with outward vertex normals, its triangles wound
// counter-clockwise seen from outside (`outward`) or from inside, as exported meshes sometimes are.
std::string sphereObj(bool outward) {
  const int rings = 24, segments = 48;
  std::string text;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const float theta = kPi * float(i) / float(rings), phi = kTwoPi * float(j) / float(segments);
      const Vec3 p(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      text += fmt::format("v {} {} {}\nvn {} {} {}\n", p.x, p.y, p.z, p.x, p.y, p.z);
    }
  auto vertex = [&](int i, int j) { return i * segments + (j % segments) + 1; };
  auto face = [&](int a, int b, int c) {
    if (!outward) std::swap(b, c);
    text += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\n", a, b, c);
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // Seen from outside, (i, j) -> (i + 1, j) -> (i + 1, j + 1) runs counter-clockwise.
      // The rows at the poles are fans: their other triangle would have two vertices at the pole.
      if (i < rings - 1) face(vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1));
      if (i > 0) face(vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1));
    }
  return text;
}

// A mesh wound against its vertex normals is shaded by them, as Mitsuba 3 and pbrt-v4 shade it: it
// rendered black with diffuse and roughconductor when the normals were turned to the winding.
TEST_F(MeshWithoutNormals, AMeshWoundAgainstItsVertexNormalsIsShadedByThem) {
  write("out.obj", sphereObj(true));
  write("in.obj", sphereObj(false));
  for (const char* bsdf :
       {"<bsdf type='diffuse'/>", "<bsdf type='roughconductor'><float name='alpha' value='0.3'/></bsdf>"}) {
    SCOPED_TRACE(bsdf);
    auto render = [&](const std::string& file) {
      const std::string xml = R"(<scene version="3.0.0"><integrator type="direct"/>
        <sensor type="perspective"><float name="fov" value="30"/>
          <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
          <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="32"/></film>
          <sampler type="independent"><integer name="sample_count" value="64"/></sampler></sensor>
        <shape type="obj"><string name="filename" value=")" +
                              (dir_ / file).string() + "\"/>" + bsdf + R"(</shape>
        <emitter type="directional"><vector name="direction" x="-0.3" y="-0.2" z="-1"/></emitter></scene>)";
      ParsedScene parsed = loadSceneString(xml, "scene.xml", dir_.string(), {}, builtinPlugins());
      Scene scene(parsed, SourceLocation{"scene.xml", 0});
      RenderStats stats;
      return renderImage(scene, RenderSettings{}, stats);
    };
    const Image out = render("out.obj"), in = render("in.obj");
    double sumOut = 0.0, sumIn = 0.0;
    for (size_t i = 0; i < out.rgb.size(); ++i) sumOut += out.rgb[i], sumIn += in.rgb[i];
    EXPECT_GT(sumOut, 1.0);
    EXPECT_NEAR(sumIn / sumOut, 1.0, 0.02);
  }
  // The geometric normal is turned to the vertex normals, so the front (and an emitter's lit side,
  // and the media a shape bounds) is theirs.
  const SurfaceInteraction si = hitFromAbove("<shape type='obj'><string name='filename' value='in.obj'/></shape>");
  EXPECT_GT(si.ng.z, 0.9f);
  EXPECT_GT(dot(si.ng, si.shading.n), 0.99f);
}

// On a mesh without uvs the shading frame's first axis (a barbule's axis) is one direction of the
// mesh projected at each point, so it turns smoothly over the surface; each triangle's first edge
// made a sphere of barbules faceted and patchy. The default is the mesh's y axis, with a warning
// where a barbule BSDF depends on it; `tangent_axis` chooses another.
TEST_F(MeshWithoutNormals, AMeshWithoutUVsGivesItsBarbulesASmoothAxis) {
  write("sphere.obj", sphereObj(true));
  std::vector<std::string> warnings;
  setWarningListener([&](const std::string& text) { warnings.push_back(text); });
  struct StopListening {
    ~StopListening() { setWarningListener(nullptr); }
  } stop;
  auto load = [&](const std::string& shape) {
    ParsedScene parsed = loadSceneString("<scene version='3.0.0'>" + shape + "</scene>", "scene.xml", dir_.string(), {},
                                         builtinPlugins());
    return std::make_unique<Scene>(parsed, SourceLocation{"scene.xml", 0});
  };
  const auto plain = load(
      "<shape type='obj'><string name='filename' value='sphere.obj'/>"
      "<bsdf type='barbulebsdf'/></shape>");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("the mesh has no uvs, so the direction its barbules run across"), std::string::npos)
      << warnings[0];
  // Rays down onto the sphere a little apart cross many triangles: the axis turns slowly, and is
  // y projected onto the surface.
  float largestTurn = 0.0f;
  std::optional<Vec3> previous;
  for (int i = 0; i <= 40; ++i) {
    const float x = -0.4f + 0.02f * float(i);
    const auto hit = plain->intersect(Ray{Vec3(x, 0.3f, 3.0f), Vec3(0, 0, -1)});
    ASSERT_TRUE(hit.has_value());
    const Vec3 n = hit->shading.n, s = hit->shading.s;
    expectNear(s, normalize(Vec3(0, 1, 0) - n * n.y), 1e-5f);
    if (previous) largestTurn = std::max(largestTurn, std::acos(std::min(1.0f, dot(*previous, s))));
    previous = s;
  }
  EXPECT_LT(largestTurn, 0.02f);  // 0.02 apart on a unit sphere: the surface turns by about as much
  warnings.clear();
  const auto along = load(
      "<shape type='obj'><string name='filename' value='sphere.obj'/>"
      "<vector name='tangent_axis' x='1' y='0' z='0'/><bsdf type='barbulebsdf'/></shape>");
  EXPECT_TRUE(warnings.empty());
  const auto top = along->intersect(Ray{Vec3(0.01f, 0.02f, 3.0f), Vec3(0, 0, -1)});
  ASSERT_TRUE(top.has_value());
  EXPECT_GT(top->shading.s.x, 0.99f);
}

}  // namespace
