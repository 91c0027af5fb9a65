#pragma once
// `sphere`: a sphere of `radius` around `center`, then `to_world`. Area emission assumes the
// transform scales uniformly (the sphere stays round).
#include "core/properties.h"
#include "shapes/analytic_shape.h"

namespace columba {

class SphereShape : public AnalyticShape {
 public:
  SphereShape(const Transform& toWorld, bool flipNormals);
  bool intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const override;
  Vec3 localNormal(const Vec3& p) const override { return flip_ ? -p : p; }
  void localBounds(Vec3& lo, Vec3& hi) const override {
    lo = Vec3(-1, -1, -1);
    hi = Vec3(1, 1, 1);
  }
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(Vec2 u, bool withTexturePoint) const override;
  std::optional<ReferenceSample> sampleFrom(const Vec3& ref, Vec2 u, bool withTexturePoint) const override;
  float pdfFrom(const Vec3& ref, const SurfaceInteraction& hit) const override;
  bool keepsRound() const { return round_; }

 private:
  // Cosine of the half-angle of the cone the sphere subtends from `ref`; nullopt when `ref`
  // is inside or the sphere is not round (then area sampling is used).
  std::optional<float> coneCosine(const Vec3& ref) const;
  // (u, v) = (phi / 2 pi, theta / pi) of a point of the unit sphere in the shape's own space.
  static Vec2 uvOf(const Vec3& local);
  bool flip_;
  bool round_;  // to_world scales uniformly
  Vec3 center_;
  float radius_, area_;
};

std::shared_ptr<Object> makeSphereShape(const Properties& props);

}  // namespace columba
