#pragma once
// Triangle meshes in world space (obj, ply, cube), intersected by Embree.
#include <optional>
#include <utility>
#include <vector>
#include "core/distribution.h"
#include "core/properties.h"
#include "core/transform.h"
#include "shapes/shape.h"
#include "textures/mesh_attributes.h"

namespace columba {

struct MeshData {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;      // per vertex, or empty
  std::vector<Vec2> uvs;          // per vertex, or empty
  std::vector<uint32_t> indices;  // 3 per triangle
  // Further per-vertex and per-triangle values of the file (PLY), for mesh_attribute textures.
  MeshAttributes attributes;
};

class TriangleMesh : public Shape {
 public:
  // Transforms `mesh` by `toWorld`; `faceNormals` ignores vertex normals, and without it a mesh
  // without normals gets smooth ones (angleWeightedVertexNormals); `flipNormals` turns the front
  // side around. Throws InputError (at `where`) for degenerate or invalid input.
  // `surfaceAxis` (in the mesh's own space; default its y axis) is the direction the shading
  // frame's first axis follows on a mesh without uvs, projected onto the surface at each point.
  TriangleMesh(MeshData mesh, const Transform& toWorld, bool faceNormals, bool flipNormals, const SourceLocation& where,
               const std::optional<Vec3>& surfaceAxis = std::nullopt);
  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(Vec2 u, bool withTexturePoint) const override;
  size_t primitiveCount() const override { return mesh_.indices.size() / 3; }
  bool hasUVs() const { return !mesh_.uvs.empty(); }

 private:
  Vec3 faceNormal(size_t tri) const;
  // The vertex normals interpolated at barycentric coordinates (b1, b2) of `tri`, unit length and
  // turned with flip_normals; nullopt without vertex normals or where they cancel.
  std::optional<Vec3> vertexNormal(size_t tri, float b1, float b2) const;
  // The geometric normal there: the face normal, turned toward the vertex normal where the
  // triangle is wound against it (the front side is the vertex normals', as Mitsuba 3 and
  // pbrt-v4 take it).
  Vec3 geometricNormal(size_t tri, const std::optional<Vec3>& vertex) const;
  // Surface derivative along u (the shading frame's first axis, as in Mitsuba).
  // dp/du and dp/dv of a triangle: from its uvs where they are usable, else from the barycentric
  // coordinates that stand in for them (p1 - p0 and p2 - p0).
  std::pair<Vec3, Vec3> positionDerivatives(size_t tri) const;
  // Where textures are looked up at barycentric coordinates (b1, b2) of triangle `tri`: the
  // interpolated uvs (or (b1, b2) without them) and the mesh's attributes there.
  TexturePoint texturePointAt(size_t tri, float b1, float b2) const;
  MeshData mesh_;
  bool flip_;
  Vec3 surfaceAxis_;  // world space, unit: the first axis's direction where there are no uvs
  float area_ = 0.0f;
  Distribution1D triangleByArea_;
  // Per triangle: the face normal (front side) and dp/du, the shading frame without vertex normals.
  std::vector<Frame> faceFrames_;
};

// Reads `face_normals` and `flip_normals`, attaches the nested BSDF and area emitter. Face normals
// are used when `face_normals` is true or the file asks for them (`fileFaceNormals`).
std::shared_ptr<Object> finishMeshShape(const Properties& props, MeshData mesh, const Transform& toWorld,
                                        bool fileFaceNormals = false);
// Attaches a shape's nested BSDF (default: diffuse 0.5, as Mitsuba), area emitter and the media it
// bounds (its `interior` and `exterior`).
void attachMaterial(const Properties& props, Shape& shape);

std::shared_ptr<Object> makeCubeShape(const Properties& props);

}  // namespace columba
