#pragma once
// Shapes defined implicitly in a local frame (unit disk, unit sphere) and placed by an affine
// `to_world`. Embree calls back into the exact local intersector (user geometry).
#include <optional>
#include "core/transform.h"
#include "shapes/shape.h"

namespace columba {

class AnalyticShape : public Shape {
 public:
  explicit AnalyticShape(const Transform& toWorld) : toWorld_(toWorld), worldToLocal_(toWorld.inverse()) {}
  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  size_t primitiveCount() const override { return 1; }

  // Nearest hit parameter in (tmin, tmax) of the local ray o + t d (d not normalised).
  virtual std::optional<float> intersectLocal(const Vec3& o, const Vec3& d, float tmin, float tmax) const = 0;
  // The same for the world ray o + t d; the map is affine, so t is the same in both frames. Shapes
  // may reject rays before transforming them.
  virtual std::optional<float> intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax) const {
    return intersectLocal(toLocalPoint(o), toLocalVector(d), tmin, tmax);
  }
  virtual Vec3 localNormal(const Vec3& localPoint) const = 0;
  // Bounds of the shape in local coordinates.
  virtual void localBounds(Vec3& lo, Vec3& hi) const = 0;

  Vec3 toWorldPoint(const Vec3& p) const { return toWorld_.point(p); }
  Vec3 toLocalPoint(const Vec3& p) const { return worldToLocal_.point(p); }
  Vec3 toLocalVector(const Vec3& v) const { return worldToLocal_.vector(v); }
  Vec3 toWorldNormal(const Vec3& n) const { return normalize(toWorld_.normal(n)); }

 protected:
  Transform toWorld_, worldToLocal_;
};

}  // namespace columba
