// Mesh attributes (a PLY's further vertex and face properties) and the mesh_attribute texture.
#include <gtest/gtest.h>

#include <cmath>

#include "builtin/builtin_plugins.h"
#include "core/math.h"
#include "scene/scene.h"
#include "shapes/ply_mesh.h"
#include "support/error_test_support.h"
#include "support/render_test_support.h"
#include "support/temp_dir_test.h"
#include "textures/mesh_attributes.h"

using namespace columba;
using namespace columba::testing;

namespace {

Wavelengths someWavelengths() { return Wavelengths::fixed({420, 500, 580, 660}); }

class MeshAttributeTextures : public TempDirTest {
 protected:
  // The unit square [-1, 1]^2 at z = 0 as one four-sided face, with a grey vertex colour that is
  // the linear function 0.5 + 0.1 x + 0.2 y (so interpolating it over either of the face's two
  // triangles gives that function exactly), and a triangle beside it; the square has face_w 0.3,
  // the triangle 0.9.
  std::string writeSquare() {
    return write("square.ply", R"(ply
format ascii 1.0
element vertex 5
property float x
property float y
property float z
property float r
property float g
property float b
element face 2
property list uchar int vertex_indices
property float w
end_header
-1 -1 0 0.2 0.2 0.2
1 -1 0 0.4 0.4 0.4
1 1 0 0.8 0.8 0.8
-1 1 0 0.6 0.6 0.6
2 0 0 0.7 0.7 0.7
4 0 1 2 3 0.3
3 1 4 2 0.9
)");
  }

  // A scene of the square with a diffuse BSDF whose reflectance is mesh attribute `name`.
  std::unique_ptr<Scene> squareScene(const std::string& name) {
    const std::string ply = writeSquare();
    ParsedScene parsed = loadSceneString(R"(<scene version="3.0.0">
      <shape type="ply"><string name="filename" value="square.ply"/>
        <bsdf type="diffuse"><texture type="mesh_attribute" name="reflectance">
          <string name="name" value=")" + name +
                                             R"("/></texture></bsdf></shape></scene>)",
                                         (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    return std::make_unique<Scene>(parsed, SourceLocation{"t.xml", 0});
  }

  // The diffuse BSDF's value straight up and back at (x, y) of the square: reflectance / pi.
  Spectrum reflectanceAt(const Scene& scene, float x, float y) {
    std::optional<SurfaceInteraction> si = scene.intersect(Ray{Vec3(x, y, 5), Vec3(0, 0, -1)});
    EXPECT_TRUE(si) << x << ", " << y;
    if (!si) return Spectrum(0.0f);
    const Vec3 up(0, 0, 1);
    return si->shape->bsdf->eval(si->bsdfContext(), up, up, someWavelengths()) * kPi;
  }
};

}  // namespace

TEST_F(MeshAttributeTextures, PlyPropertiesAreGroupedAndNamedAsMitsubas) {
  const std::string path = write("named.ply", R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property float u
property float v
property uchar red
property uchar green
property uchar blue
property uchar alpha
property float quality
property float dir_x
property float dir_y
property float dir_z
property float k_1
property float k_2
element face 1
property list uchar int vertex_indices
property uchar r
property uchar g
property uchar b
property short weight
end_header
0 0 0 0 0 255 128 0 7 0.5 1 2 3 4 5
1 0 0 1 0 0 0 0 7 0.5 1 2 3 4 5
0 1 0 0 1 0 0 0 7 0.5 1 2 3 4 5
3 0 1 2 255 0 0 -32767
)");
  MeshData mesh = readPlyMesh(path);
  // Three components group under their stem (alpha is read past); two do not group.
  EXPECT_EQ(mesh.attributes.names(),
            "vertex_color, vertex_quality, vertex_dir, vertex_k_1, vertex_k_2, face_color, "
            "face_weight");
  const MeshAttributes::Attribute* colour = mesh.attributes.find(MeshAttributeKey("vertex_color"));
  ASSERT_TRUE(colour);
  EXPECT_EQ(colour->channels, 3);
  // Integers are divided by their type's largest value and decoded from sRGB, as Mitsuba reads them.
  EXPECT_FLOAT_EQ(colour->values[0], 1.0f);
  EXPECT_NEAR(colour->values[1], std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f), 1e-6f);
  const MeshAttributes::Attribute* dir = mesh.attributes.find(MeshAttributeKey("vertex_dir"));
  ASSERT_TRUE(dir);
  EXPECT_EQ(dir->channels, 3);
  EXPECT_FLOAT_EQ(dir->values[2], 3.0f);  // floats are kept as they are
  EXPECT_FLOAT_EQ(mesh.attributes.find(MeshAttributeKey("face_weight"))->values[0], -1.0f / 12.92f);
  EXPECT_FALSE(mesh.attributes.find(MeshAttributeKey("vertex_alpha")));
}

TEST_F(MeshAttributeTextures, LoneFirstComponentIsNamedByItsStem) {
  // Mitsuba writes a one-channel attribute face_weight as the property weight_0 and reads it back
  // under its stem; a lone _x or _1 is read the same way, a second component keeps both apart.
  const std::string path = write("lone.ply", R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property float height_x
property float k_1
property float k_2
element face 1
property list uchar int vertex_indices
property float weight_0
end_header
0 0 0 0.25 1 2
1 0 0 0.25 1 2
0 1 0 0.25 1 2
3 0 1 2 0.75
)");
  MeshData mesh = readPlyMesh(path);
  EXPECT_EQ(mesh.attributes.names(), "vertex_height, vertex_k_1, vertex_k_2, face_weight");
  const MeshAttributes::Attribute* weight = mesh.attributes.find(MeshAttributeKey("face_weight"));
  ASSERT_TRUE(weight);
  EXPECT_EQ(weight->channels, 1);
  EXPECT_FLOAT_EQ(weight->values[0], 0.75f);
}

TEST(MeshAttributes, VertexValuesAreInterpolatedAndFaceValuesHeld) {
  MeshAttributes attributes;
  attributes.add("vertex_h", 1, {0.0f, 1.0f, 2.0f, 4.0f});
  attributes.add("face_w", 1, {0.25f, 0.75f});
  const std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
  attributes.setTriangles(triangles);
  const MeshAttributes::Attribute& h = *attributes.find(MeshAttributeKey("vertex_h"));
  // Barycentric (0.25, 0.5): 0.25 * h0 + 0.25 * h1 + 0.5 * h2.
  EXPECT_FLOAT_EQ(attributes.evalFloat(h, 0, Vec2(0.25f, 0.5f)), 0.25f + 1.0f);
  EXPECT_FLOAT_EQ(attributes.evalFloat(h, 1, Vec2(0.25f, 0.5f)), 0.5f + 2.0f);
  // A polygon split into triangles gives each triangle the polygon's value.
  attributes.expandFacesToTriangles({0, 0, 1});
  const MeshAttributes::Attribute& w = *attributes.find(MeshAttributeKey("face_w"));
  EXPECT_FLOAT_EQ(attributes.evalFloat(w, 1, Vec2(0.3f, 0.3f)), 0.25f);
  EXPECT_FLOAT_EQ(attributes.evalFloat(w, 2, Vec2(0.3f, 0.3f)), 0.75f);
  EXPECT_FLOAT_EQ(h.mean, 7.0f / 4.0f);
}

TEST(MeshAttributes, ColoursBlendTheirVerticesSpectra) {
  MeshAttributes attributes;
  attributes.add("vertex_color", 3, {0.9f, 0.1f, 0.1f, 0.1f, 0.9f, 0.1f, 0.1f, 0.1f, 0.9f});
  const std::vector<uint32_t> triangle = {0, 1, 2};
  attributes.setTriangles(triangle);
  const MeshAttributes::Attribute& c = *attributes.find(MeshAttributeKey("vertex_color"));
  const Wavelengths wl = someWavelengths();
  const Spectrum mixed = attributes.evalSpectrum(c, 0, Vec2(0.2f, 0.5f), wl);
  for (int i = 0; i < kSpectrumSamples; ++i) {
    const float expected =
        0.3f * c.spectra[0].eval(wl[i]) + 0.2f * c.spectra[1].eval(wl[i]) + 0.5f * c.spectra[2].eval(wl[i]);
    EXPECT_NEAR(mixed[i], expected, 1e-6f);
  }
  // As a number: the luminance of the blended colour (luminance is linear).
  EXPECT_NEAR(attributes.evalFloat(c, 0, Vec2(0.2f, 0.5f)), linearRGBToXYZ(Vec3(0.34f, 0.26f, 0.50f)).y, 1e-6f);
}

TEST_F(MeshAttributeTextures, AReflectanceFollowsTheVertexColours) {
  auto scene = squareScene("vertex_color");
  for (auto [x, y] : {std::pair{0.0f, 0.0f}, std::pair{0.5f, -0.25f}, std::pair{-0.7f, 0.6f}, std::pair{0.9f, 0.8f},
                      std::pair{-0.9f, -0.95f}}) {
    const Spectrum r = reflectanceAt(*scene, x, y);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(r[i], 0.5f + 0.1f * x + 0.2f * y, 1e-5f) << x << ", " << y;
  }
}

TEST_F(MeshAttributeTextures, FaceValuesHoldOverTheirFace) {
  auto scene = squareScene("face_w");
  for (auto [x, y, w] : {std::tuple{-0.5f, 0.5f, 0.3f}, std::tuple{0.5f, -0.5f, 0.3f}, std::tuple{1.3f, 0.1f, 0.9f}}) {
    const Spectrum r = reflectanceAt(*scene, x, y);
    for (int i = 0; i < kSpectrumSamples; ++i) EXPECT_NEAR(r[i], w, 1e-6f) << x << ", " << y;
  }
}

TEST_F(MeshAttributeTextures, ARenderStopsAtAShapeWithoutTheAttribute) {
  writeSquare();
  const std::string xml = R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="40"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>
    <texture type="mesh_attribute" id="colours"><string name="name" value="vertex_color"/></texture>
    <shape type="sphere"><bsdf type="diffuse"><ref name="reflectance" id="colours"/></bsdf></shape>
    <emitter type="constant"/>
    </scene>)";
  ParsedScene parsed = loadSceneString(xml, (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
  Scene scene(parsed, SourceLocation{"t.xml", 0});
  RenderStats stats;
  try {
    renderImage(scene, RenderSettings{}, stats);
    ADD_FAILURE() << "the render did not stop";
  } catch (const InputError& e) {
    expectContains(e.what(), {"t.xml:5", "mesh_attribute 'vertex_color'", "not a mesh"});
  }
  const std::string ply = (dir_ / "square.ply").string();
  expectContains(
      [&] {
        try {
          renderSceneString(R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="40"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/></film></sensor>
    <shape type="ply"><string name="filename" value=")" +
                            ply + R"("/>
      <bsdf type="diffuse"><texture type="mesh_attribute" name="reflectance">
        <string name="name" value="vertex_weight"/></texture></bsdf></shape>
    <emitter type="constant"/></scene>)");
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"mesh_attribute 'vertex_weight'", "its attributes: vertex_color, face_w"});
}

TEST_F(MeshAttributeTextures, NamesMustSayVertexOrFace) {
  try {
    loadSceneString(R"(<scene version="3.0.0">
      <texture type="mesh_attribute" id="t"><string name="name" value="color"/></texture></scene>)",
                    (dir_ / "t.xml").string(), dir_.string(), {}, builtinPlugins());
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    expectContains(e.what(), {"t.xml:2", "starts with vertex_ or face_", "'color'"});
  }
}
