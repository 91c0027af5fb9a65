#include "shapes/planar_shape.h"

namespace columba {

PlanarShape::PlanarShape(const Transform& toWorld, bool flipNormals, float localArea)
    : AnalyticShape(toWorld), flip_(flipNormals) {
  // An affine map scales all areas of the plane by the same factor.
  area_ = localArea * length(cross(toWorld_.vector(Vec3(1, 0, 0)), toWorld_.vector(Vec3(0, 1, 0))));
  frame_ = Frame::fromNormalAndS(toWorldNormal(localNormal(Vec3())), toWorld_.vector(Vec3(1, 0, 0)));
}

std::optional<float> PlanarShape::intersectLocal(const Vec3& o, const Vec3& d, float tmin, float tmax) const {
  if (d.z == 0.0f) return std::nullopt;
  float t = -o.z / d.z;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  Vec3 p = o + d * t;
  if (!contains(Vec2(p.x, p.y))) return std::nullopt;
  return t;
}

std::optional<float> PlanarShape::intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax) const {
  // Most rays that reach the shape's bounds miss its plane within (tmin, tmax): that needs only
  // the local z of the ray (the same arithmetic as the full transform's).
  const auto& toLocalZ = worldToLocal_.matrix().m[2];
  float dz = float(toLocalZ[0] * d.x + toLocalZ[1] * d.y + toLocalZ[2] * d.z);
  float oz = float(toLocalZ[0] * o.x + toLocalZ[1] * o.y + toLocalZ[2] * o.z + toLocalZ[3]);
  if (dz == 0.0f) return std::nullopt;
  float t = -oz / dz;
  if (!(t > tmin && t < tmax)) return std::nullopt;
  return intersectLocal(toLocalPoint(o), toLocalVector(d), tmin, tmax);
}

SurfaceInteraction PlanarShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  // Re-projected onto the plane: ray.at(t) is off it by the rounding of t, which can exceed the
  // offset of rays spawned from the point.
  Vec3 local = toLocalPoint(ray.at(hit.t));
  si.p = toWorldPoint(Vec3(local.x, local.y, 0.0f));
  si.ng = frame_.n;
  si.uv = uvAt(Vec2(local.x, local.y));
  si.shading = frame_;
  return si;
}

PositionSample PlanarShape::samplePosition(Vec2 u) const {
  Vec2 local = sampleLocal(u);
  PositionSample ps;
  ps.p = toWorldPoint(Vec3(local.x, local.y, 0));
  ps.n = frame_.n;
  ps.pdfArea = 1.0f / area_;
  return ps;
}

}  // namespace columba
