#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "shapes/ply_mesh.h"

using namespace columba;

namespace {

// A unit square in z = 0 as one quad, and a triangle of area 0.5 in z = 1. The square's vertex
// normals lean towards +x so that tests can tell them from its face normal +z.
struct Vertex {
  float x, y, z, nx, ny, nz, u, v;
};
const Vertex kVertices[] = {{0, 0, 0, 0.6f, 0, 0.8f, 0, 0}, {1, 0, 0, 0.6f, 0, 0.8f, 1, 0},
                            {1, 1, 0, 0.6f, 0, 0.8f, 1, 1}, {0, 1, 0, 0.6f, 0, 0.8f, 0, 1},
                            {0, 0, 1, 0, 0, 1, 0, 0},       {1, 0, 1, 0, 0, 1, 0, 0},
                            {0, 1, 1, 0, 0, 1, 0, 0}};
const std::vector<std::vector<int>> kFaces = {{0, 1, 2, 3}, {4, 5, 6}};
constexpr float kArea = 1.5f;

class PlyMeshTest : public ::testing::Test {
 protected:
  static std::filesystem::path dir() {
    return std::filesystem::temp_directory_path() / ("columba_ply_mesh_test_" + std::to_string(getpid()));
  }
  static std::string path(const std::string& name) {
    std::filesystem::create_directories(dir());
    return (dir() / name).string();
  }
  void TearDown() override { std::filesystem::remove_all(dir()); }

  static std::string write(const std::string& name, const std::string& content) {
    std::string p = path(name);
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

  // ASCII: 15 header lines, then one line per vertex (line 16 is vertex 0) and per face.
  static std::string ascii(size_t declaredVertices = 7) {
    std::ostringstream s;
    s << "ply\nformat ascii 1.0\ncomment a quad and a triangle\nelement vertex " << declaredVertices << "\n"
      << "property float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
      << "property float nz\nproperty float u\nproperty float v\nelement face " << kFaces.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
    for (const Vertex& v : kVertices)
      s << v.x << " " << v.y << " " << v.z << " " << v.nx << " " << v.ny << " " << v.nz << " " << v.u << " " << v.v
        << "\n";
    for (const auto& f : kFaces) {
      s << f.size();
      for (int i : f) s << " " << i;
      s << "\n";
    }
    return s.str();
  }
  static constexpr int kFirstVertexLine = 16;

  // Binary with other types and names: double positions, uint8 colour, s t, vertex_index as
  // ushort uint, and a trailing element to skip. `badY` replaces vertex 1's y.
  static std::string binary(double badY = 0.0) {
    std::ostringstream s;
    s << "ply\nformat binary_little_endian 1.0\nelement vertex 7\nproperty double x\nproperty double y\n"
      << "property double z\nproperty uint8 red\nproperty float nx\nproperty float ny\nproperty float nz\n"
      << "property float s\nproperty float t\nelement face 2\nproperty list ushort uint vertex_index\n"
      << "element material 1\nproperty int id\nend_header\n";
    auto put = [&](const auto& value) { s.write(reinterpret_cast<const char*>(&value), sizeof(value)); };
    for (size_t i = 0; i < std::size(kVertices); ++i) {
      const Vertex& v = kVertices[i];
      put(double(v.x));
      put(i == 1 && badY != 0.0 ? badY : double(v.y));
      put(double(v.z));
      put(uint8_t(9));
      put(v.nx);
      put(v.ny);
      put(v.nz);
      put(v.u);
      put(v.v);
    }
    for (const auto& f : kFaces) {
      put(uint16_t(f.size()));
      for (int i : f) put(uint32_t(i));
    }
    put(int32_t(3));
    return s.str();
  }

  // The InputError message of reading `file`, or "" if it loaded.
  static std::string errorOf(const std::string& file) {
    try {
      readPlyMesh(file);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  static ParsedScene loadScene(const std::string& shapeParams) {
    std::string xml = "<scene version='3.0.0'>\n<shape type=\"ply\">\n  <string name='filename' value='mesh.ply'/>\n" +
                      shapeParams + "</shape>\n</scene>\n";
    return loadSceneString(xml, "scene.xml", dir().string(), {}, builtinPlugins());
  }
};

// Replaces the `field`th value (0-based) on line `line` (1-based) of `text`.
std::string replaceValue(std::string text, int line, int field, const std::string& value) {
  size_t pos = 0;
  for (int l = 1; l < line; ++l) pos = text.find('\n', pos) + 1;
  for (int f = 0; f < field; ++f) pos = text.find(' ', pos) + 1;
  size_t end = text.find_first_of(" \n", pos);
  return text.replace(pos, end - pos, value);
}

}  // namespace

TEST_F(PlyMeshTest, ReadsAsciiAndTriangulatesQuads) {
  MeshData m = readPlyMesh(write("a.ply", ascii()));
  ASSERT_EQ(m.positions.size(), 7u);
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 4, 5, 6}));
  ASSERT_EQ(m.normals.size(), 7u);
  EXPECT_FLOAT_EQ(m.normals[2].x, 0.6f);
  ASSERT_EQ(m.uvs.size(), 7u);
  EXPECT_FLOAT_EQ(m.uvs[2].x, 1.0f);
  EXPECT_FLOAT_EQ(m.uvs[3].y, 1.0f);
}

TEST_F(PlyMeshTest, BinaryWithOtherTypesAndNamesMatchesAscii) {
  MeshData a = readPlyMesh(write("a.ply", ascii()));
  MeshData b = readPlyMesh(write("b.ply", binary()));
  ASSERT_EQ(a.positions.size(), b.positions.size());
  for (size_t i = 0; i < a.positions.size(); ++i) {
    EXPECT_EQ(a.positions[i], b.positions[i]);
    EXPECT_EQ(a.normals[i], b.normals[i]);
    EXPECT_EQ(a.uvs[i].x, b.uvs[i].x);
    EXPECT_EQ(a.uvs[i].y, b.uvs[i].y);
  }
  EXPECT_EQ(a.indices, b.indices);
}

TEST_F(PlyMeshTest, NormalsAndTextureCoordinatesAreOptional) {
  std::string text =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float texture_u\nproperty float texture_v\nelement face 1\n"
      "property list uchar uint vertex_indices\nend_header\n"
      "0 0 0 1 0.25 0.5\n1 0 0 1 0 0\n0 1 0 1 0 0\n3 0 1 2\n";
  MeshData m = readPlyMesh(write("partial.ply", text));
  EXPECT_TRUE(m.normals.empty());  // nx alone is not a normal
  ASSERT_EQ(m.uvs.size(), 3u);
  EXPECT_FLOAT_EQ(m.uvs[0].x, 0.25f);
  EXPECT_FLOAT_EQ(m.uvs[0].y, 0.5f);
}

TEST_F(PlyMeshTest, LoadsThroughASceneWithAreaAndNormals) {
  write("mesh.ply", ascii());
  ParsedScene parsed = loadScene(
      "  <transform name='to_world'><scale value='2'/></transform>\n"
      "  <bsdf type='diffuse'/>\n");
  ASSERT_EQ(parsed.objects.size(), 1u);
  auto mesh = std::dynamic_pointer_cast<TriangleMesh>(parsed.objects[0]);
  ASSERT_TRUE(mesh);
  EXPECT_TRUE(mesh->bsdf);
  EXPECT_EQ(mesh->primitiveCount(), 3u);
  EXPECT_NEAR(mesh->surfaceArea(), 4.0f * kArea, 1e-5f);

  // A hit inside the quad's second triangle: geometric normal +z, shading normal the file's.
  HitRecord hit;
  hit.primID = 1;
  hit.u = hit.v = 0.25f;
  SurfaceInteraction si = mesh->interaction(Ray(), hit);
  EXPECT_NEAR(si.ng.z, 1.0f, 1e-6f);
  EXPECT_NEAR(si.shading.n.x, 0.6f, 1e-5f);
  EXPECT_NEAR(si.shading.n.z, 0.8f, 1e-5f);
  EXPECT_NEAR(si.p.x, 2.0f * 0.25f, 1e-5f);
  EXPECT_NEAR(si.p.y, 2.0f * 0.5f, 1e-5f);

  auto flipped = std::dynamic_pointer_cast<TriangleMesh>(
      loadScene("  <boolean name='face_normals' value='true'/>\n  <boolean name='flip_normals' value='true'/>\n")
          .objects[0]);
  si = flipped->interaction(Ray(), hit);
  EXPECT_NEAR(si.ng.z, -1.0f, 1e-6f);
  EXPECT_NEAR(si.shading.n.z, -1.0f, 1e-6f);
}

TEST_F(PlyMeshTest, SceneErrorsNameThePlyFile) {
  std::string f = write("mesh.ply", replaceValue(ascii(), kFirstVertexLine + 7, 2, "9"));
  try {
    loadScene("");
    FAIL() << "an index out of range was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(f + ":" + std::to_string(kFirstVertexLine + 7)), std::string::npos)
        << e.what();
  }
}

TEST_F(PlyMeshTest, ReportsIndicesOutOfRangeAtTheirLine) {
  std::string f = write("range.ply", replaceValue(ascii(), kFirstVertexLine + 8, 3, "7"));
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kFirstVertexLine + 8)), std::string::npos) << err;
  EXPECT_NE(err.find("face 1"), std::string::npos) << err;
  EXPECT_NE(err.find("out of range"), std::string::npos) << err;
}

TEST_F(PlyMeshTest, ReportsFacesWithFewerThanThreeIndices) {
  std::string text = ascii();
  text.replace(text.rfind("3 4 5 6"), 7, "2 4 5");
  std::string f = write("short.ply", text);
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kFirstVertexLine + 8)), std::string::npos) << err;
  EXPECT_NE(err.find("2 vertex indices"), std::string::npos) << err;
}

TEST_F(PlyMeshTest, ReportsNonFiniteCoordinates) {
  for (const char* bad : {"nan", "inf", "1e39"}) {
    std::string f = write("nan.ply", replaceValue(ascii(), kFirstVertexLine + 1, 1, bad));
    std::string err = errorOf(f);
    EXPECT_NE(err.find(f + ":" + std::to_string(kFirstVertexLine + 1)), std::string::npos) << bad << ": " << err;
    EXPECT_NE(err.find("'y'"), std::string::npos) << err;
  }
  std::string b = write("nan.bin.ply", binary(std::nan("")));
  std::string err = errorOf(b);
  EXPECT_NE(err.find(b + ": vertex 1: property 'y'"), std::string::npos) << err;
}

TEST_F(PlyMeshTest, ReportsMissingCoordinatesAtTheElementLine) {
  std::string text = ascii();
  text.replace(text.find("property float z\n"), 17, "");
  std::string f = write("noz.ply", text);
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":4"), std::string::npos) << err;
  EXPECT_NE(err.find("'z'"), std::string::npos) << err;
}

TEST_F(PlyMeshTest, ReportsWrongVertexCountsAndTruncatedFiles) {
  // One vertex more than the file has: vertex 7 is read from the first face line.
  std::string f = write("count.ply", ascii(8));
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kFirstVertexLine + 7)), std::string::npos) << err;
  EXPECT_NE(err.find("vertex 7"), std::string::npos) << err;

  std::string text = ascii();
  text.resize(text.rfind('\n', text.size() - 2) + 1);  // drop the last face
  f = write("cut.ply", text);
  err = errorOf(f);
  EXPECT_NE(err.find(f + ":" + std::to_string(kFirstVertexLine + 8)), std::string::npos) << err;
  EXPECT_NE(err.find("truncated"), std::string::npos) << err;

  std::string bytes = binary();
  bytes.resize(bytes.size() - 4 - 8);  // into the triangle's indices
  f = write("cut.bin.ply", bytes);
  err = errorOf(f);
  EXPECT_NE(err.find(f + ": "), std::string::npos) << err;
  EXPECT_NE(err.find("face 1"), std::string::npos) << err;
  EXPECT_NE(err.find("truncated"), std::string::npos) << err;
}

TEST_F(PlyMeshTest, ReportsFilesWithoutFaces) {
  std::string text = ascii();
  text.replace(text.find("element face 2"), 14, "element face 0");
  text.resize(text.find("4 0 1 2 3"));
  std::string f = write("nofaces.ply", text);
  std::string err = errorOf(f);
  EXPECT_NE(err.find(f + ":15"), std::string::npos) << err;
  EXPECT_NE(err.find("no faces"), std::string::npos) << err;
}
