#include "shapes/disk_shape.h"

#include "core/sampling.h"
#include "shapes/triangle_mesh.h"

namespace columba {

DiskShape::DiskShape(const Transform& toWorld, bool flipNormals) : AnalyticShape(toWorld), flip_(flipNormals) {
  // An affine map scales all areas of the plane by the same factor.
  area_ = kPi * length(cross(toWorld_.vector(Vec3(1, 0, 0)), toWorld_.vector(Vec3(0, 1, 0))));
  normal_ = toWorldNormal(localNormal(Vec3()));
}

std::optional<float> DiskShape::intersectLocal(const Vec3& o, const Vec3& d, float tmin, float tmax) const {
  if (d.z == 0.0f) return std::nullopt;
  float t = -o.z / d.z;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  Vec3 p = o + d * t;
  if (p.x * p.x + p.y * p.y > 1.0f) return std::nullopt;
  return t;
}

std::optional<float> DiskShape::intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax) const {
  // Most rays that reach the disk's bounds miss its plane within (tmin, tmax): that needs only the
  // local z of the ray (the same arithmetic as the full transform's).
  const auto& toLocalZ = worldToLocal_.matrix().m[2];
  float dz = float(toLocalZ[0] * d.x + toLocalZ[1] * d.y + toLocalZ[2] * d.z);
  float oz = float(toLocalZ[0] * o.x + toLocalZ[1] * o.y + toLocalZ[2] * o.z + toLocalZ[3]);
  if (dz == 0.0f) return std::nullopt;
  float t = -oz / dz;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  return intersectLocal(toLocalPoint(o), toLocalVector(d), tmin, tmax);
}

SurfaceInteraction DiskShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  si.p = ray.at(hit.t);
  si.ng = normal_;
  Vec3 local = toLocalPoint(si.p);
  float r = std::sqrt(local.x * local.x + local.y * local.y);
  float phi = std::atan2(local.y, local.x);
  si.uv = Vec2(r, (phi < 0 ? phi + kTwoPi : phi) * (0.5f * kInvPi));
  si.shading = Frame::fromNormalAndS(si.ng, toWorld_.vector(Vec3(1, 0, 0)));
  return si;
}

PositionSample DiskShape::samplePosition(Vec2 u) const {
  Vec2 d = sampleConcentricDisk(u);
  PositionSample ps;
  ps.p = toWorldPoint(Vec3(d.x, d.y, 0));
  ps.n = normal_;
  ps.pdfArea = 1.0f / area_;
  return ps;
}

std::shared_ptr<Object> makeDiskShape(const Properties& props) {
  auto shape = std::make_shared<DiskShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
