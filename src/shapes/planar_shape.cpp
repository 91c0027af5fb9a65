#include "shapes/planar_shape.h"

namespace columba {

PlanarShape::PlanarShape(const Transform& toWorld, bool flipNormals, float localArea)
    : AnalyticShape(toWorld), flip_(flipNormals) {
  // An affine map scales all areas of the plane by the same factor.
  axisX_ = toWorld_.vector(Vec3(1, 0, 0));
  axisY_ = toWorld_.vector(Vec3(0, 1, 0));
  origin_ = toWorld_.point(Vec3(0, 0, 0));
  area_ = localArea * length(cross(axisX_, axisY_));
  frame_ = Frame::fromNormalAndS(toWorldNormal(localNormal(Vec3())), axisX_);
  const auto& m = worldToLocal_.matrix().m;
  for (int i = 0; i < 3; ++i) {
    localRows_[i] = Vec3(float(m[i][0]), float(m[i][1]), float(m[i][2]));
    localOffsets_[i] = float(m[i][3]);
  }
}

Vec3 PlanarShape::localCoordinates(const Vec3& p) const {
  return {dot(localRows_[0], p) + localOffsets_[0], dot(localRows_[1], p) + localOffsets_[1],
          dot(localRows_[2], p) + localOffsets_[2]};
}

bool PlanarShape::intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const {
  // The plane is where the local z vanishes: t = num / dz. Most rays that reach the shape's bounds
  // miss the plane within (tmin, tmax), which is tested before dividing.
  float dz = dot(localRows_[2], d);
  float num = -(dot(localRows_[2], o) + localOffsets_[2]);
  if (dz < 0.0f) {
    dz = -dz;
    num = -num;
  }
  if (!(num > tmin * dz && num < tmax * dz)) return false;
  t = num / dz;
  if (!(t > tmin && t < tmax)) return false;
  Vec3 p = o + d * t;
  return contains(Vec2(dot(localRows_[0], p) + localOffsets_[0], dot(localRows_[1], p) + localOffsets_[1]));
}

SurfaceInteraction PlanarShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  // Re-projected onto the plane: ray.at(t) is off it by the rounding of t, which can exceed the
  // offset of rays spawned from the point.
  Vec3 local = localCoordinates(ray.at(hit.t));
  si.p = worldPoint(Vec2(local.x, local.y));
  si.ng = frame_.n;
  si.uv = uvAt(Vec2(local.x, local.y));
  const auto [du, dv] = localPositionDerivatives(Vec2(local.x, local.y));
  si.dpdu = axisX_ * du.x + axisY_ * du.y;
  si.dpdv = axisX_ * dv.x + axisY_ * dv.y;
  si.shading = frame_;
  return si;
}

PositionSample PlanarShape::samplePosition(Vec2 u, bool withTexturePoint) const {
  PositionSample ps;
  const Vec2 local = sampleLocal(u);
  ps.p = worldPoint(local);
  ps.n = frame_.n;
  if (withTexturePoint) ps.point = uvAt(local);
  ps.pdfArea = 1.0f / area_;
  return ps;
}

}  // namespace columba
