/*! plugin shape ply
A triangle mesh read from a PLY file (ASCII or binary), with a nested BSDF (default: `diffuse`) and optionally an `area` emitter. A vertex's or face's further properties become mesh attributes named as Mitsuba names them, for `mesh_attribute` textures: consecutive `{p}_x/y/z`, `{p}_r/g/b`, `{p}_0/1/2` or `{p}_1/2/3` make `vertex_{p}` (or `face_{p}`), `r/g/b` and `red/green/blue` make `vertex_color`, a lone first component (`{p}_0` not followed by `{p}_1`, and so on) makes the one-channel `vertex_{p}` (Mitsuba writes `face_weight` as `weight_0`), others `vertex_{name}`; a fourth component is read past, as attributes have 1 or 3 channels; integers are divided by their type's largest value and decoded from sRGB; a polygon's face values go to each of its triangles.
Mitsuba 3: the same parameters and defaults.
uses: mesh, media
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the PLY file | same |
| to_world | transform | identity | places the mesh | same |
*/
#include "shapes/ply_mesh.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_set>

#include "io/ply_file.h"
#include "shapes/ply_attributes.h"

namespace columba {

namespace {

// Property indices of the vertex attributes the mesh uses; -1 where the file has none.
struct VertexLayout {
  int position[3];
  int normal[3] = {-1, -1, -1};
  int uv[2] = {-1, -1};
  bool hasNormals() const { return normal[0] >= 0; }
  bool hasUVs() const { return uv[0] >= 0; }
};

VertexLayout vertexLayout(const PlyReader& ply, const PlyElement& e) {
  VertexLayout layout;
  const char* axes[3] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    layout.position[a] = e.findScalar(axes[a]);
    if (layout.position[a] < 0)
      throw ply.headerError(e, std::string("element vertex has no property '") + axes[a] + "'");
  }
  // Normals and texture coordinates count only when complete.
  int n[3] = {e.findScalar("nx"), e.findScalar("ny"), e.findScalar("nz")};
  if (n[0] >= 0 && n[1] >= 0 && n[2] >= 0) std::copy(n, n + 3, layout.normal);
  for (auto [u, v] : {std::pair{"u", "v"}, std::pair{"s", "t"}, std::pair{"texture_u", "texture_v"}}) {
    int iu = e.findScalar(u), iv = e.findScalar(v);
    if (iu >= 0 && iv >= 0) {
      layout.uv[0] = iu;
      layout.uv[1] = iv;
      break;
    }
  }
  return layout;
}

// The values of attribute groups, one vector per group, filled record by record.
struct AttributeValues {
  std::vector<PlyAttributeGroup> groups;
  std::vector<std::vector<float>> values;

  AttributeValues(const PlyElement& e, const std::string& prefix, const std::unordered_set<std::string>& reserved)
      : groups(plyAttributeGroups(e, prefix, reserved)), values(groups.size()) {
    for (size_t g = 0; g < groups.size(); ++g) values[g].reserve(e.count * groups[g].properties.size());
  }
  void read(const PlyReader& ply, const PlyElement& e) {
    for (size_t g = 0; g < groups.size(); ++g)
      for (int property : groups[g].properties) {
        const float v = plyAttributeValue(ply.scalar(size_t(property)), e.properties[size_t(property)].type);
        if (!std::isfinite(v)) ply.fail("property '" + e.properties[size_t(property)].name + "' is not a finite float");
        values[g].push_back(v);
      }
  }
  void addTo(MeshAttributes& attributes) {
    for (size_t g = 0; g < groups.size(); ++g)
      attributes.add(groups[g].name, int(groups[g].properties.size()), std::move(values[g]));
  }
};

void readVertices(PlyReader& ply, const PlyElement& e, MeshData& mesh) {
  const VertexLayout layout = vertexLayout(ply, e);
  std::unordered_set<std::string> reserved;
  for (int property : layout.position) reserved.insert(e.properties[size_t(property)].name);
  if (layout.hasNormals())
    for (int property : layout.normal) reserved.insert(e.properties[size_t(property)].name);
  if (layout.hasUVs())
    for (int property : layout.uv) reserved.insert(e.properties[size_t(property)].name);
  AttributeValues attributes(e, "vertex_", reserved);
  mesh.positions.reserve(e.count);
  if (layout.hasNormals()) mesh.normals.reserve(e.count);
  if (layout.hasUVs()) mesh.uvs.reserve(e.count);
  auto value = [&](int property) {
    float v = float(ply.scalar(size_t(property)));
    if (!std::isfinite(v)) ply.fail("property '" + e.properties[size_t(property)].name + "' is not a finite float");
    return v;
  };
  for (size_t i = 0; i < e.count; ++i) {
    ply.next();
    mesh.positions.push_back(Vec3(value(layout.position[0]), value(layout.position[1]), value(layout.position[2])));
    if (layout.hasNormals())
      mesh.normals.push_back(Vec3(value(layout.normal[0]), value(layout.normal[1]), value(layout.normal[2])));
    if (layout.hasUVs()) mesh.uvs.push_back(Vec2(value(layout.uv[0]), value(layout.uv[1])));
    attributes.read(ply, e);
  }
  attributes.addTo(mesh.attributes);
}

void readFaces(PlyReader& ply, const PlyElement& e, MeshData& mesh) {
  const int list = ply.vertexIndexList(e);
  const size_t vertexCount = mesh.positions.size();
  mesh.indices.reserve(3 * e.count);
  AttributeValues attributes(e, "face_", {});
  std::vector<uint32_t> triangleFace;  // the face each triangle comes from
  for (size_t i = 0; i < e.count; ++i) {
    ply.next();
    attributes.read(ply, e);
    const std::vector<double>& face = ply.list(size_t(list));
    if (face.size() < 3) ply.fail("has " + std::to_string(face.size()) + " vertex indices; a face needs at least 3");
    const uint32_t first = ply.vertexIndex(face[0], vertexCount);
    uint32_t previous = ply.vertexIndex(face[1], vertexCount);
    for (size_t k = 2; k < face.size(); ++k) {
      const uint32_t current = ply.vertexIndex(face[k], vertexCount);
      mesh.indices.insert(mesh.indices.end(), {first, previous, current});
      if (!attributes.groups.empty()) triangleFace.push_back(uint32_t(i));
      previous = current;
    }
  }
  if (attributes.groups.empty()) return;
  attributes.addTo(mesh.attributes);
  mesh.attributes.expandFacesToTriangles(triangleFace);
}

}  // namespace

MeshData readPlyMesh(const std::string& path) {
  PlyReader ply(path, "PLY file");
  MeshData mesh;
  bool sawVertex = false, sawFace = false;
  for (const PlyElement& e : ply.elements()) {
    if (e.name == "vertex" && !sawVertex) {
      readVertices(ply, e, mesh);
      sawVertex = true;
    } else if (e.name == "face" && !sawFace) {
      if (!sawVertex) throw ply.headerError(e, "element face must come after element vertex");
      readFaces(ply, e, mesh);
      sawFace = true;
    } else {
      for (size_t i = 0; i < e.count; ++i) ply.next();
    }
  }
  if (!sawVertex) throw InputError({path, ply.endHeaderLine()}, "the file has no element vertex");
  if (mesh.indices.empty()) throw InputError({path, ply.endHeaderLine()}, "the file has no faces");
  ply.finish();
  return mesh;
}

std::shared_ptr<Object> makePlyShape(const Properties& props) {
  return finishMeshShape(props, readPlyMesh(props.getPath("filename")), props.getTransform("to_world"));
}

}  // namespace columba
