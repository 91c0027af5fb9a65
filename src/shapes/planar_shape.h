#pragma once
// Flat shapes in the local plane z = 0 within [-1, 1]^2, facing +z (or -z with `flip_normals`),
// placed by an affine `to_world`: `disk` and `rectangle`. They are intersected exactly, as
// Mitsuba 3 does, and share one flat shading frame (s along the local x axis, dp/du).
#include <utility>
#include "shapes/analytic_shape.h"

namespace columba {

class PlanarShape : public AnalyticShape {
 public:
  // `localArea`: the shape's area in its local plane.
  PlanarShape(const Transform& toWorld, bool flipNormals, float localArea);

  bool intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const override;
  Vec3 localNormal(const Vec3&) const override { return Vec3(0, 0, flip_ ? -1.0f : 1.0f); }
  Vec3 worldNormal(const Vec3&) const override { return frame_.n; }
  void localBounds(Vec3& lo, Vec3& hi) const override {
    lo = Vec3(-1, -1, 0);
    hi = Vec3(1, 1, 0);
  }
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  float surfaceArea() const override { return area_; }
  PositionSample samplePosition(Vec2 u, bool withTexturePoint) const override;

 protected:
  // Whether the local point (x, y) of the plane belongs to the shape.
  virtual bool contains(Vec2 local) const = 0;
  virtual Vec2 uvAt(Vec2 local) const = 0;
  // dp/du and dp/dv at a local point, as local vectors (x, y) in the plane.
  virtual std::pair<Vec2, Vec2> localPositionDerivatives(Vec2 local) const = 0;
  // A local point uniformly distributed over the shape.
  virtual Vec2 sampleLocal(Vec2 u) const = 0;

 private:
  // Local coordinates of a world point (worldToLocal_ in single precision, as rays are).
  Vec3 localCoordinates(const Vec3& p) const;
  // The world point at local (x, y, 0).
  Vec3 worldPoint(Vec2 local) const { return origin_ + axisX_ * local.x + axisY_ * local.y; }

  bool flip_;
  float area_;
  Frame frame_;  // world shading frame, the same everywhere; frame_.n is the front normal
  Vec3 localRows_[3];
  float localOffsets_[3];
  Vec3 origin_, axisX_, axisY_;  // the world images of the local origin and of the x and y axes
};

}  // namespace columba
