#pragma once
// `disk`: the unit disk in the local xy plane, facing +z.
#include "scene/properties.h"
#include "shapes/analytic_shape.h"

namespace columba {

class DiskShape : public AnalyticShape {
 public:
  DiskShape(const Transform& toWorld, bool flipNormals);
  std::optional<float> intersectLocal(const Vec3& o, const Vec3& d, float tmin, float tmax) const override;
  std::optional<float> intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax) const override;
  Vec3 localNormal(const Vec3&) const override { return Vec3(0, 0, flip_ ? -1.0f : 1.0f); }
  void localBounds(Vec3& lo, Vec3& hi) const override { lo = Vec3(-1, -1, 0); hi = Vec3(1, 1, 0); }
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(Vec2 u) const override;

 private:
  bool flip_;
  float area_;
  Vec3 normal_;  // world-space front normal, the same everywhere on the disk
};

std::shared_ptr<Object> makeDiskShape(const Properties& props);

}  // namespace columba
