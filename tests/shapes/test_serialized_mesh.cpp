#include <gtest/gtest.h>
#include <zlib.h>

#include <unistd.h>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "builtin/builtin_plugins.h"
#include "scene/scene_loader.h"
#include "shapes/serialized_mesh.h"

using namespace columba;

namespace {

// Files in Mitsuba's serialized format, written here field by field from the format's
// description, independently of the reader.
class Bytes {
 public:
  template <typename T>
  Bytes& put(T value) {
    for (size_t i = 0; i < sizeof(T); ++i) data_.push_back(char((uint64_t(value) >> (8 * i)) & 0xFF));
    return *this;
  }
  Bytes& putReal(double v, bool doublePrecision) {
    if (doublePrecision) {
      uint64_t bits;
      std::memcpy(&bits, &v, 8);
      return put(bits);
    }
    float f = float(v);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    return put(bits);
  }
  Bytes& append(const std::string& s) {
    data_ += s;
    return *this;
  }
  const std::string& str() const { return data_; }

 private:
  std::string data_;
};

struct TestMesh {
  std::vector<float> positions, normals, uvs;
  std::vector<uint32_t> indices;
};

// A unit square in z = 0 (two triangles) with normals leaning toward +x and texture coordinates;
// `shift` moves it along z so that meshes of one file can be told apart.
TestMesh square(float shift) {
  return {{0, 0, shift, 1, 0, shift, 1, 1, shift, 0, 1, shift},
          {0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f},
          {0, 0, 1, 0, 1, 1, 0, 1},
          {0, 1, 2, 0, 2, 3}};
}

std::string compressed(const std::string& raw) {
  uLongf size = compressBound(uLong(raw.size()));
  std::string out(size, '\0');
  EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                      uLong(raw.size()), 6),
            Z_OK);
  out.resize(size);
  return out;
}

std::string meshRecord(const TestMesh& m, uint16_t version, uint32_t flags, bool doublePrecision) {
  Bytes body;
  body.put(flags | (doublePrecision ? 0x2000u : 0x1000u));
  if (version == 4) body.append("square").put(uint8_t(0));
  body.put(uint64_t(m.positions.size() / 3)).put(uint64_t(m.indices.size() / 3));
  for (float v : m.positions) body.putReal(v, doublePrecision);
  if (flags & 0x0001)
    for (float v : m.normals) body.putReal(v, doublePrecision);
  if (flags & 0x0002)
    for (float v : m.uvs) body.putReal(v, doublePrecision);
  if (flags & 0x0008)
    for (size_t i = 0; i < m.positions.size(); ++i) body.putReal(0.5, doublePrecision);
  for (uint32_t i : m.indices) body.put(i);
  return Bytes().put(uint16_t(0x041C)).put(version).append(compressed(body.str())).str();
}

// The meshes one after another, then the dictionary of their offsets and their count.
std::string serializedFile(const std::vector<std::string>& records, uint16_t version) {
  Bytes file;
  std::vector<uint64_t> offsets;
  for (const std::string& r : records) {
    offsets.push_back(file.str().size());
    file.append(r);
  }
  for (uint64_t o : offsets) version == 4 ? file.put(o) : file.put(uint32_t(o));
  return file.put(uint32_t(records.size())).str();
}

std::string expectError(const std::string& bytes, int index = 0) {
  try {
    parseSerializedMesh(bytes, index, "mesh.serialized");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

}  // namespace

TEST(SerializedMesh, ReadsEveryAttributeInBothVersionsAndPrecisions) {
  for (uint16_t version : {uint16_t(3), uint16_t(4)})
    for (bool doublePrecision : {false, true}) {
      std::string bytes =
          serializedFile({meshRecord(square(0), version, 0x0001 | 0x0002 | 0x0008, doublePrecision)}, version);
      SerializedMesh s = parseSerializedMesh(bytes, 0, "mesh.serialized");
      const MeshData& m = s.mesh;
      ASSERT_EQ(m.positions.size(), 4u);
      ASSERT_EQ(m.normals.size(), 4u);
      ASSERT_EQ(m.uvs.size(), 4u);
      EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
      EXPECT_EQ(m.positions[2].x, 1.0f);
      EXPECT_EQ(m.positions[2].y, 1.0f);
      EXPECT_EQ(m.normals[1].x, 0.6f);
      EXPECT_EQ(m.normals[1].z, 0.8f);
      EXPECT_EQ(m.uvs[3].y, 1.0f);
      EXPECT_FALSE(s.faceNormals);
    }
}

TEST(SerializedMesh, ShapeIndexPicksAMeshThroughTheDictionary) {
  for (uint16_t version : {uint16_t(3), uint16_t(4)}) {
    std::string bytes =
        serializedFile({meshRecord(square(0), version, 0, false), meshRecord(square(2), version, 0x0010, true),
                        meshRecord(square(5), version, 0x0002, false)},
                       version);
    SerializedMesh second = parseSerializedMesh(bytes, 1, "mesh.serialized");
    EXPECT_EQ(second.mesh.positions[0].z, 2.0f);
    EXPECT_TRUE(second.mesh.normals.empty());
    EXPECT_TRUE(second.faceNormals);
    SerializedMesh third = parseSerializedMesh(bytes, 2, "mesh.serialized");
    EXPECT_EQ(third.mesh.positions[3].z, 5.0f);
    EXPECT_EQ(third.mesh.uvs.size(), 4u);
    EXPECT_NE(expectError(bytes, 3).find("shape_index 3 is out of range: the file holds 3 meshes"), std::string::npos);
  }
}

TEST(SerializedMesh, ReportsBadInputWithTheFileAndMesh) {
  std::string good = serializedFile({meshRecord(square(0), 4, 0, false)}, 4);
  EXPECT_NE(expectError("ab").find("mesh.serialized: too short"), std::string::npos);
  std::string wrongMagic = good;
  wrongMagic[0] = 0x1D;
  EXPECT_NE(expectError(wrongMagic).find("not a Mitsuba serialized mesh"), std::string::npos);
  std::string wrongVersion = good;
  wrongVersion[2] = 5;
  EXPECT_NE(expectError(wrongVersion).find("version 5 is not supported"), std::string::npos);

  // Truncated compressed data, a corrupt stream, an index past the vertices, counts too large to
  // be in the file (nothing is allocated for them), a non-finite position.
  EXPECT_NE(expectError(good.substr(0, 30)).find("mesh.serialized: mesh 0: the compressed data ends"),
            std::string::npos);
  std::string corrupt = good;
  corrupt[4] = char(0xFF);
  EXPECT_NE(expectError(corrupt).find("mesh 0: corrupt compressed data"), std::string::npos);
  TestMesh far = square(0);
  far.indices[4] = 7;
  EXPECT_NE(expectError(serializedFile({meshRecord(far, 4, 0, false)}, 4))
                .find("mesh 0: triangle 1 refers to vertex 7, but the mesh has 4 vertices"),
            std::string::npos);
  Bytes huge;
  huge.put(uint32_t(0x1000)).append("x").put(uint8_t(0)).put(uint64_t(1) << 31).put(uint64_t(1) << 40);
  std::string hugeFile = Bytes().put(uint16_t(0x041C)).put(uint16_t(4)).append(compressed(huge.str())).str();
  EXPECT_NE(expectError(hugeFile).find("cannot fit in the file's"), std::string::npos);
  TestMesh nan = square(0);
  nan.positions[4] = std::nanf("");
  EXPECT_NE(expectError(serializedFile({meshRecord(nan, 4, 0, false)}, 4))
                .find("vertex positions value 4 is not a finite number"),
            std::string::npos);
}

TEST(SerializedMesh, LoadsThroughASceneWithFaceNormalsFromTheFileOrTheScene) {
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("columba_serialized_test_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "two.serialized", std::ios::binary)
      << serializedFile({meshRecord(square(0), 4, 0x0001, false), meshRecord(square(1), 4, 0x0001 | 0x0010, false)}, 4);
  auto load = [&](const std::string& params) {
    std::string xml =
        "<scene version='3.0.0'>\n<shape type='serialized'>\n  <string name='filename' value='two.serialized'/>\n" +
        params + "</shape>\n</scene>\n";
    ParsedScene parsed = loadSceneString(xml, "scene.xml", dir.string(), {}, builtinPlugins());
    auto mesh = std::dynamic_pointer_cast<TriangleMesh>(parsed.objects.at(0));
    EXPECT_TRUE(mesh);
    HitRecord hit;
    hit.primID = 1;
    hit.u = hit.v = 0.25f;
    return mesh->interaction(Ray(), hit);
  };
  // The file's normals lean toward +x; scaled by 2, the point moves with the transform.
  SurfaceInteraction si = load("  <transform name='to_world'><scale value='2'/></transform>\n");
  EXPECT_NEAR(si.shading.n.x, 0.6f, 1e-5f);
  EXPECT_NEAR(si.p.x, 2.0f * 0.25f, 1e-5f);
  // Face normals: asked by the scene, or by the second mesh's flag.
  EXPECT_NEAR(load("  <boolean name='face_normals' value='true'/>\n").shading.n.z, 1.0f, 1e-6f);
  si = load("  <integer name='shape_index' value='1'/>\n");
  EXPECT_NEAR(si.shading.n.z, 1.0f, 1e-6f);
  EXPECT_NEAR(si.p.z, 1.0f, 1e-6f);
  try {
    load("  <integer name='shape_index' value='-1'/>\n");
    ADD_FAILURE() << "a negative shape_index was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scene.xml:4"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}
