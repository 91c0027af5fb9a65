/*! plugin shape obj
A triangle mesh read from a Wavefront OBJ file (polygons are split into triangles), with a nested BSDF (default: `diffuse`) and optionally an `area` emitter.
Mitsuba 3: the same parameters and defaults.
uses: mesh, media
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the OBJ file | same |
| to_world | transform | identity | places the mesh | same |
| flip_tex_coords | boolean | true | v becomes 1 − v (OBJ puts v = 0 at an image's bottom, textures at its top) | same |
*/
#include "shapes/obj_mesh.h"

#include <tiny_obj_loader.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace columba {

namespace {

// What tinyobjloader does not check: it reads a malformed or non-finite number as 0, skips faces
// of fewer than three corners and counts a face's corners in a byte. Returns the line of each
// face statement, in file order.
std::vector<int> checkStatements(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0}, "cannot open the OBJ file");
  std::vector<int> faceLines;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    std::istringstream words(line);
    std::string keyword, word;
    words >> keyword;
    if (keyword == "f") {
      int corners = 0;
      while (words >> word) ++corners;
      if (corners < 3 || corners > 255)
        throw InputError({path, lineNo}, "a face needs 3 to 255 corners, this one has " + std::to_string(corners));
      faceLines.push_back(lineNo);
    } else if (keyword == "v" || keyword == "vn" || keyword == "vt") {
      while (words >> word) {
        float value = 0;
        auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (ec == std::errc::result_out_of_range)
          throw InputError({path, lineNo}, "'" + word + "' is out of the range of a float");
        if (ec != std::errc() || end != word.data() + word.size() || !std::isfinite(value))
          throw InputError({path, lineNo}, "'" + word + "' is not a finite number");
      }
    }
  }
  return faceLines;
}

// Checks the corners of one face against the file's vertex, normal and texture coordinate counts.
class FaceChecker {
 public:
  FaceChecker(std::string path, std::vector<int> faceLines, const tinyobj::attrib_t& attrib)
      : path_(std::move(path)), faceLines_(std::move(faceLines)), attrib_(attrib) {}

  void check(size_t face, const tinyobj::index_t& corner) const {
    // Indices are reported as the file numbers them (from 1).
    auto inRange = [&](int index, size_t count, const char* what, const char* plural) {
      if (index < 0 || size_t(index) >= count)
        throw InputError({path_, face < faceLines_.size() ? faceLines_[face] : 0},
                         "face " + std::to_string(face + 1) + ": " + what + " index " + std::to_string(index + 1) +
                             " is out of range (the file has " + std::to_string(count) + " " + plural + ")");
    };
    inRange(corner.vertex_index, attrib_.vertices.size() / 3, "vertex", "vertices");
    if (corner.normal_index != -1) inRange(corner.normal_index, attrib_.normals.size() / 3, "normal", "normals");
    if (corner.texcoord_index != -1)
      inRange(corner.texcoord_index, attrib_.texcoords.size() / 2, "texture coordinate", "texture coordinates");
  }

 private:
  std::string path_;
  std::vector<int> faceLines_;
  const tinyobj::attrib_t& attrib_;
};

// The triangles of a polygon whose corners are the mesh vertices `corners`, in order.
void triangulate(const MeshData& mesh, const std::vector<uint32_t>& corners, std::vector<uint32_t>& indices) {
  const uint32_t* c = corners.data();
  if (corners.size() == 4) {
    // tinyobjloader's split (the shorter diagonal), so that quads triangulate as they always have.
    Vec3 d02 = mesh.positions[c[2]] - mesh.positions[c[0]], d13 = mesh.positions[c[3]] - mesh.positions[c[1]];
    if (dot(d02, d02) < dot(d13, d13))
      indices.insert(indices.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
    else
      indices.insert(indices.end(), {c[0], c[1], c[3], c[1], c[2], c[3]});
    return;
  }
  for (size_t k = 2; k < corners.size(); ++k) indices.insert(indices.end(), {c[0], c[k - 1], c[k]});
}

}  // namespace

MeshData readObjMesh(const std::string& path) {
  std::vector<int> faceLines = checkStatements(path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // tinyobjloader's triangulation would read unchecked indices
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) {
    std::string message = reader.Error();
    while (!message.empty() && (message.back() == '\n' || message.back() == '.')) message.pop_back();
    throw InputError({path, 0}, "cannot read the OBJ file: " + message);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const FaceChecker checker(path, std::move(faceLines), attrib);

  bool useNormals = true, useUVs = true;
  size_t face = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t corner = 0;
    for (unsigned char corners : shape.mesh.num_face_vertices) {
      for (size_t k = 0; k < corners; ++k, ++corner) {
        const tinyobj::index_t& idx = shape.mesh.indices[corner];
        checker.check(face, idx);
        useNormals &= idx.normal_index >= 0;
        useUVs &= idx.texcoord_index >= 0;
      }
      ++face;
    }
  }

  // OBJ indexes positions, normals and uvs separately. As in Mitsuba, there is one mesh vertex per
  // distinct combination the faces use, so faces meeting at a corner share its computed normal.
  MeshData mesh;
  std::map<std::array<int, 3>, uint32_t> vertexOfCorner;
  std::vector<uint32_t> corners;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t corner = 0;
    for (unsigned char count : shape.mesh.num_face_vertices) {
      corners.clear();
      for (size_t k = 0; k < count; ++k, ++corner) {
        const tinyobj::index_t& idx = shape.mesh.indices[corner];
        const std::array<int, 3> key = {idx.vertex_index, useUVs ? idx.texcoord_index : -1,
                                        useNormals ? idx.normal_index : -1};
        auto [it, added] = vertexOfCorner.emplace(key, uint32_t(mesh.positions.size()));
        corners.push_back(it->second);
        if (!added) continue;
        const float* p = &attrib.vertices[3 * size_t(idx.vertex_index)];
        mesh.positions.push_back(Vec3(p[0], p[1], p[2]));
        if (useNormals) {
          const float* n = &attrib.normals[3 * size_t(idx.normal_index)];
          mesh.normals.push_back(Vec3(n[0], n[1], n[2]));
        }
        if (useUVs) {
          const float* uv = &attrib.texcoords[2 * size_t(idx.texcoord_index)];
          mesh.uvs.push_back(Vec2(uv[0], uv[1]));
        }
      }
      triangulate(mesh, corners, mesh.indices);
    }
  }
  if (mesh.indices.empty()) throw InputError({path, 0}, "the OBJ file has no faces");
  return mesh;
}

std::shared_ptr<Object> makeObjShape(const Properties& props) {
  MeshData mesh = readObjMesh(props.getPath("filename"));
  // OBJ files put v = 0 at the bottom of an image, textures at the top: Mitsuba flips v by default.
  if (props.getBool("flip_tex_coords", true))
    for (Vec2& uv : mesh.uvs) uv.y = 1.0f - uv.y;
  return finishMeshShape(props, std::move(mesh), props.getTransform("to_world"));
}

}  // namespace columba
