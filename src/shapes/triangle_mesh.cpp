/*! parameters media
| parameter | type | default | meaning | Mitsuba 3 |
| interior | medium | none | the medium inside the shape (behind its normals), a nested `<medium name="interior">` or a `<ref name="interior" id="..."/>`: a ray crossing the surface inward travels in it | same |
| exterior | medium | none | the medium outside (on the side of its normals); a shape bounding neither leaves a ray in the medium it was in | same |
*/
/*! parameters mesh
| parameter | type | default | meaning | Mitsuba 3 |
| face_normals | boolean | false | flat shading with each triangle's own normal, ignoring the file's normals; a mesh without normals is otherwise shaded with smooth vertex normals, each face weighted by its angle at the vertex | same |
| tangent_axis | vector | (0, 1, 0) | on a mesh without uvs, the direction that stands in for dp/du (in the mesh's own space, placed by `to_world`), projected onto the surface at each point: the shading frame's x. Barbules (`barbulebsdf`, `barbulearms`) run along its y, n × x, across this direction. With uvs, dp/du gives x, as in Mitsuba (a tangent_axis then warns that it has no effect); a barbule BSDF on a mesh with neither warns that the default was chosen | Columba's own |
| flip_normals | boolean | false | turns the normals (and the side an area emitter lights) around. The front side is the side of the vertex normals where the mesh has them (a triangle wound against its vertex normals is shaded, lit and bounds media by them), else that from which the triangle's vertices run counter-clockwise | same |
*/
/*! plugin shape cube
The cube [−1, 1]³ as a mesh of twelve triangles with face normals and per-face uv, placed by `to_world`. Like every shape, it takes a nested BSDF (default: `diffuse`) and may take a nested `area` emitter.
Mitsuba 3: as Mitsuba 3's `cube`.
uses: mesh, media
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | places the cube | same |
*/
#include "shapes/triangle_mesh.h"

#include <tuple>

#include <cmath>

#include "bsdfs/diffuse.h"
#include "core/sampling.h"
#include "emitters/emitter.h"
#include "media/medium.h"
#include "shapes/vertex_normals.h"

namespace columba {

TriangleMesh::TriangleMesh(MeshData mesh, const Transform& toWorld, bool faceNormals, bool flipNormals,
                           const SourceLocation& where, const std::optional<Vec3>& surfaceAxis)
    : mesh_(std::move(mesh)), flip_(flipNormals) {
  // One direction for the whole mesh, projected at each point, so that the frame turns smoothly
  // with the surface (each triangle's first edge made a sphere of barbules patchy).
  const Vec3 axis = toWorld.vector(surfaceAxis.value_or(Vec3(0, 1, 0)));
  if (!(length(axis) > 0.0f) || !isFinite(axis))
    throw InputError(where, "tangent_axis must be a finite, non-zero direction");
  surfaceAxis_ = normalize(axis);
  if (mesh_.indices.empty() || mesh_.indices.size() % 3 != 0) throw InputError(where, "the mesh has no triangles");
  for (uint32_t i : mesh_.indices)
    if (i >= mesh_.positions.size())
      throw InputError(where, "triangle index " + std::to_string(i) + " is out of range (" +
                                  std::to_string(mesh_.positions.size()) + " vertices)");
  for (Vec3& p : mesh_.positions) {
    p = toWorld.point(p);
    if (!isFinite(p)) throw InputError(where, "the mesh has a non-finite vertex position");
  }
  if (faceNormals) {
    mesh_.normals.clear();
  } else if (mesh_.normals.empty()) {
    // As Mitsuba: a mesh without normals is shaded smooth, its normals made from the world-space faces.
    mesh_.normals = angleWeightedVertexNormals(mesh_.positions, mesh_.indices);
  } else {
    for (Vec3& n : mesh_.normals) {
      n = toWorld.normal(n);
      float len = length(n);
      n = len > 0 ? n / len : Vec3(0, 0, 1);
    }
  }
  std::vector<float> areas(primitiveCount());
  for (size_t t = 0; t < areas.size(); ++t) {
    const Vec3& a = mesh_.positions[mesh_.indices[3 * t]];
    areas[t] = 0.5f * length(cross(mesh_.positions[mesh_.indices[3 * t + 1]] - a,
                                   mesh_.positions[mesh_.indices[3 * t + 2]] - a));
    area_ += areas[t];
    if (!std::isfinite(areas[t]))
      throw InputError(where, "triangle " + std::to_string(t) + " is too large: its area overflows single precision");
  }
  if (!std::isfinite(area_)) throw InputError(where, "the mesh's total area overflows single precision");
  if (area_ > 0.0f) triangleByArea_ = Distribution1D(std::move(areas));
  if (!mesh_.attributes.empty()) mesh_.attributes.setTriangles(mesh_.indices);
  faceFrames_.resize(primitiveCount());
  for (size_t t = 0; t < faceFrames_.size(); ++t)
    faceFrames_[t] =
        Frame::fromNormalAndS(faceNormal(t), mesh_.uvs.empty() ? surfaceAxis_ : positionDerivatives(t).first);
}

unsigned TriangleMesh::addToEmbree(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh_.positions.data(), 0,
                             sizeof(Vec3), mesh_.positions.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh_.indices.data(), 0,
                             3 * sizeof(uint32_t), primitiveCount());
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

std::pair<Vec3, Vec3> TriangleMesh::positionDerivatives(size_t tri) const {
  const uint32_t* idx = &mesh_.indices[3 * tri];
  const Vec3 &p0 = mesh_.positions[idx[0]], &p1 = mesh_.positions[idx[1]], &p2 = mesh_.positions[idx[2]];
  if (!mesh_.uvs.empty()) {
    Vec2 d02 = mesh_.uvs[idx[0]] - mesh_.uvs[idx[2]], d12 = mesh_.uvs[idx[1]] - mesh_.uvs[idx[2]];
    float det = d02.x * d12.y - d02.y * d12.x;
    if (std::abs(det) > 1e-12f)
      return {((p0 - p2) * d12.y - (p1 - p2) * d02.y) / det, ((p1 - p2) * d02.x - (p0 - p2) * d12.x) / det};
  }
  return {p1 - p0, p2 - p0};  // the first edge also keeps the frame stable
}

Vec3 TriangleMesh::faceNormal(size_t tri) const {
  const Vec3& a = mesh_.positions[mesh_.indices[3 * tri]];
  Vec3 n = normalize(
      cross(mesh_.positions[mesh_.indices[3 * tri + 1]] - a, mesh_.positions[mesh_.indices[3 * tri + 2]] - a));
  return flip_ ? -n : n;
}

std::optional<Vec3> TriangleMesh::vertexNormal(size_t tri, float b1, float b2) const {
  if (mesh_.normals.empty()) return std::nullopt;
  const uint32_t* idx = &mesh_.indices[3 * tri];
  const Vec3 n = mesh_.normals[idx[0]] * (1.0f - b1 - b2) + mesh_.normals[idx[1]] * b1 + mesh_.normals[idx[2]] * b2;
  const float len = length(n);
  if (!(len > 0.0f)) return std::nullopt;
  return flip_ ? -n / len : n / len;
}

Vec3 TriangleMesh::geometricNormal(size_t tri, const std::optional<Vec3>& vertex) const {
  const Vec3& n = faceFrames_[tri].n;
  return vertex && dot(*vertex, n) < 0.0f ? -n : n;
}

SurfaceInteraction TriangleMesh::interaction(const Ray& ray, const HitRecord& hit) const {
  const uint32_t* idx = &mesh_.indices[3 * size_t(hit.primID)];
  const Frame& face = faceFrames_[hit.primID];
  float b1 = hit.u, b2 = hit.v, b0 = 1.0f - b1 - b2;
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  si.p = mesh_.positions[idx[0]] * b0 + mesh_.positions[idx[1]] * b1 + mesh_.positions[idx[2]] * b2;
  const std::optional<Vec3> ns = vertexNormal(size_t(hit.primID), b1, b2);
  si.ng = geometricNormal(size_t(hit.primID), ns);
  si.shading = face;
  // dp/du lies in the face's plane, so the face frame's s has its direction; without uvs the
  // mesh's axis is projected at the point itself. A vanishing interpolated normal (computed
  // normals that cancel) leaves the face frame.
  if (ns) si.shading = Frame::fromNormalAndS(*ns, mesh_.uvs.empty() ? surfaceAxis_ : face.s);
  const TexturePoint where = texturePointAt(hit.primID, b1, b2);
  si.uv = where.uv;
  si.meshAttributes = where.mesh;
  si.triangle = where.triangle;
  si.barycentric = where.barycentric;
  std::tie(si.dpdu, si.dpdv) = positionDerivatives(hit.primID);
  return si;
}

PositionSample TriangleMesh::samplePosition(Vec2 u, bool withTexturePoint) const {
  float reuse;
  size_t tri = triangleByArea_.sampleDiscrete(u.x, &reuse);
  Vec2 b = sampleUniformTriangle(Vec2(reuse, u.y));
  const uint32_t* idx = &mesh_.indices[3 * tri];
  PositionSample ps;
  ps.p = mesh_.positions[idx[0]] * (1.0f - b.x - b.y) + mesh_.positions[idx[1]] * b.x + mesh_.positions[idx[2]] * b.y;
  ps.n = geometricNormal(tri, vertexNormal(tri, b.x, b.y));
  if (withTexturePoint) ps.point = texturePointAt(tri, b.x, b.y);
  ps.pdfArea = 1.0f / area_;
  return ps;
}

TexturePoint TriangleMesh::texturePointAt(size_t tri, float b1, float b2) const {
  const uint32_t* idx = &mesh_.indices[3 * tri];
  const float b0 = 1.0f - b1 - b2;
  TexturePoint p(mesh_.uvs.empty() ? Vec2(b1, b2)
                                   : mesh_.uvs[idx[0]] * b0 + mesh_.uvs[idx[1]] * b1 + mesh_.uvs[idx[2]] * b2);
  if (!mesh_.attributes.empty()) {
    p.mesh = &mesh_.attributes;
    p.triangle = uint32_t(tri);
    p.barycentric = Vec2(b1, b2);
  }
  return p;
}

void attachMaterial(const Properties& props, Shape& shape) {
  shape.bsdf = props.child<BSDF>();
  // Mitsuba's default material: a plain diffuse BSDF with its default reflectance.
  if (!shape.bsdf) shape.bsdf = makeDefaultPlugin<BSDF>(makeDiffuseBSDF, "bsdf", "diffuse", props.location);
  shape.interior = props.namedChild<Medium>("interior");
  shape.exterior = props.namedChild<Medium>("exterior");
  shape.emitter = props.child<Emitter>();
  if (shape.emitter) {
    if (!(shape.surfaceArea() > 0.0f))
      throw InputError(props.location, "an area emitter needs a shape with positive area");
    shape.emitter->attachTo(&shape);
  }
}

std::shared_ptr<Object> finishMeshShape(const Properties& props, MeshData mesh, const Transform& toWorld,
                                        bool fileFaceNormals) {
  bool faceNormals = props.getBool("face_normals", false) || fileFaceNormals;
  const std::optional<Vec3> axis =
      props.has("tangent_axis") ? std::optional<Vec3>(props.getVector("tangent_axis", Vec3(0, 1, 0))) : std::nullopt;
  auto shape = std::make_shared<TriangleMesh>(std::move(mesh), toWorld, faceNormals,
                                              props.getBool("flip_normals", false), props.location, axis);
  attachMaterial(props, *shape);
  if (!shape->hasUVs() && !axis && shape->bsdf && shape->bsdf->followsSurfaceAxis())
    warn(props.location,
         "the mesh has no uvs, so the direction its barbules run across (the shading frame's x, which dp/du gives "
         "elsewhere) is the mesh's own y axis projected onto the surface, a choice of Columba's, undefined where the "
         "surface faces along y: give the mesh uvs, or <vector name=\"tangent_axis\"> to choose it");
  if (axis && shape->hasUVs())
    warn(props.locationOf("tangent_axis"), "tangent_axis has no effect: the mesh has uvs, whose dp/du gives the axis");
  return shape;
}

std::shared_ptr<Object> makeCubeShape(const Properties& props) {
  MeshData m;
  // Six faces, four vertices each, wound counter-clockwise seen from outside.
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      Vec3 n(0, 0, 0), a(0, 0, 0), b(0, 0, 0);
      n[axis] = sign;
      a[(axis + 1) % 3] = 1;
      b[(axis + 2) % 3] = 1;
      if (sign < 0) std::swap(a, b);
      uint32_t base = uint32_t(m.positions.size());
      for (Vec2 c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
        m.positions.push_back(n + a * c.x + b * c.y);
        m.normals.push_back(n);
        m.uvs.push_back(Vec2(0.5f * (c.x + 1), 0.5f * (c.y + 1)));
      }
      for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
    }
  return finishMeshShape(props, std::move(m), props.getTransform("to_world"));
}

}  // namespace columba
