#include <gtest/gtest.h>

#include <unistd.h>
#include "support/temp_dir_test.h"

#include <filesystem>
#include <fstream>

#include "shapes/obj_mesh.h"

using namespace columba;
namespace fs = std::filesystem;

namespace {

class ObjMeshTest : public columba::testing::TempDirTest {
 protected:
  std::string write(const std::string& text) { return TempDirTest::write("mesh.obj", text); }
  // The message of the InputError that reading `text` as an OBJ file throws ("" if none).
  std::string readError(const std::string& text) {
    try {
      readObjMesh(write(text));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_F(ObjMeshTest, ReadsPositionsNormalsAndTextureCoordinates) {
  MeshData mesh =
      readObjMesh(write(std::string(kTriangle) + "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/1 3/3/1\n"));
  ASSERT_EQ(mesh.indices.size(), 3u);
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.normals.size(), 3u);
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(mesh.positions[mesh.indices[1]].x, 1.0f);
  EXPECT_EQ(mesh.uvs[mesh.indices[2]].y, 1.0f);
}

TEST_F(ObjMeshTest, QuadsSplitAlongTheShorterDiagonalAndPolygonsFan) {
  // A quad whose 1-3 diagonal is the shorter: triangles (0 1 3) and (1 2 3).
  MeshData quad = readObjMesh(write("v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 0.5 0\nf 1 2 3 4\n"));
  EXPECT_EQ(quad.indices, (std::vector<uint32_t>{0, 1, 3, 1, 2, 3}));
  MeshData pentagon = readObjMesh(write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 1.5 0\nv 0 1 0\nf 1 2 3 4 5\n"));
  EXPECT_EQ(pentagon.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
}

TEST_F(ObjMeshTest, CornersWithTheSameIndicesShareAVertex) {
  // Two triangles of a square share the corners 1 and 3, so a computed normal is shared there.
  MeshData square = readObjMesh(write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"));
  EXPECT_EQ(square.positions.size(), 4u);
  EXPECT_EQ(square.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  // A texture seam at corner 1 (texture coordinates 1 and 4 there) keeps two vertices.
  MeshData seam = readObjMesh(
      write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0\nf 1/1 2/2 3/3\nf 1/4 3/3 4/1\n"));
  EXPECT_EQ(seam.positions.size(), 5u);
  EXPECT_EQ(seam.indices, (std::vector<uint32_t>{0, 1, 2, 3, 2, 4}));
}

TEST_F(ObjMeshTest, IndicesOutOfRangeNameTheFaceLineAndIndex) {
  struct Case {
    std::string faces;
    std::vector<std::string> expected;
  };
  std::vector<Case> cases = {
      {"f 1//1 2//1 3//1\n", {"mesh.obj:4", "face 1", "normal index 1", "0 normals"}},
      {"f 1/1 2/1 3/1\n", {"mesh.obj:4", "face 1", "texture coordinate index 1", "0 texture coordinates"}},
      {"f 1 2 3\n\nf 1 2 1000000\n", {"mesh.obj:6", "face 2", "vertex index 1000000", "3 vertices"}},
      {"vn 0 0 1\nf 1//1 2//1 3//2\n", {"mesh.obj:5", "face 1", "normal index 2", "1 normals"}},
      {"vt 0 0\nf 1/1 2/1 3/2\n", {"mesh.obj:5", "face 1", "texture coordinate index 2"}},
      {"f 1 2 3 -4\n", {"mesh.obj:4", "face 1", "vertex index 0"}},  // relative, one before the first
      {"f 1 2\n", {"mesh.obj:4", "3 to 255 corners"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.faces);
    std::string message = readError(kTriangle + c.faces);
    for (const std::string& fragment : c.expected) EXPECT_NE(message.find(fragment), std::string::npos) << message;
  }
}

TEST_F(ObjMeshTest, NonFiniteOrMalformedNumbersAreRejected) {
  for (std::string bad : {"nan", "inf", "-inf", "1e39", "0x1p3", "1,5"}) {
    SCOPED_TRACE(bad);
    std::string message = readError("v 0 0 0\nv " + bad + " 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_NE(message.find("mesh.obj:2"), std::string::npos) << message;
    EXPECT_NE(message.find("'" + bad + "'"), std::string::npos) << message;
  }
  EXPECT_NE(readError(std::string(kTriangle) + "vn 0 nan 1\nf 1//1 2//1 3//1\n").find("mesh.obj:4"), std::string::npos);
}

TEST_F(ObjMeshTest, AFileWithoutFacesIsAnError) { EXPECT_NE(readError(kTriangle).find("no faces"), std::string::npos); }
