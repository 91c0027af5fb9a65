#pragma once
// `cylinder`: the open tube (no end caps) of `radius` around the segment from `p0` to `p1`, then
// `to_world`, as Mitsuba defines it: locally the unit tube x^2 + y^2 = 1, 0 <= z <= 1, mapped by
// to_world * translate(p0) * frame(p1 - p0) * scale(radius, radius, |p1 - p0|), normals outward
// unless `flip_normals`; uv = (angle / 2 pi, z), the shading frame's s along dp/du. Area emission
// assumes the transform keeps the tube round (no shear, equal scale across the axis).
#include "core/properties.h"
#include "shapes/analytic_shape.h"

namespace columba {

class CylinderShape : public AnalyticShape {
 public:
  CylinderShape(const Transform& toWorld, bool flipNormals);
  bool intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const override;
  Vec3 localNormal(const Vec3& p) const override { return flip_ ? Vec3(-p.x, -p.y, 0) : Vec3(p.x, p.y, 0); }
  void localBounds(Vec3& lo, Vec3& hi) const override {
    lo = Vec3(-1, -1, 0);
    hi = Vec3(1, 1, 1);
  }
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(Vec2 u, bool withTexturePoint) const override;
  // Whether to_world keeps the tube round: its area is then 2 pi radius length, sampled uniformly.
  bool keepsRound() const { return round_; }

 private:
  bool flip_, round_;
  float area_;
};

std::shared_ptr<Object> makeCylinderShape(const Properties& props);

}  // namespace columba
