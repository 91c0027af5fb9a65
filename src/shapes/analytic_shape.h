#pragma once
// Shapes defined implicitly in a local frame (unit disk, unit sphere) and placed by an affine
// `to_world`. Embree calls back into their exact intersectors (user geometry).
#include <optional>
#include "core/transform.h"
#include "shapes/shape.h"

namespace columba {

class AnalyticShape : public Shape {
 public:
  explicit AnalyticShape(const Transform& toWorld) : toWorld_(toWorld), worldToLocal_(toWorld.inverse()) {}
  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  size_t primitiveCount() const override { return 1; }

  // Whether the world ray o + t d (d not normalised) hits the shape within (tmin, tmax), and the
  // nearest such t. The map is affine, so t is also the parameter of the local ray. (A bool and an
  // out parameter: an optional<float> return is assembled in memory, a store-forwarding stall in
  // the hottest callback.)
  virtual bool intersectWorld(const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const = 0;
  virtual Vec3 localNormal(const Vec3& localPoint) const = 0;
  // Unit geometric normal at a world point on the shape.
  virtual Vec3 worldNormal(const Vec3& worldPoint) const {
    return toWorldNormal(localNormal(toLocalPoint(worldPoint)));
  }
  // The one primitive's hit and normal, as userGeometryIntersect asks for them.
  bool intersectPrimitive(unsigned, const Vec3& o, const Vec3& d, float tmin, float tmax, float& t) const {
    return intersectWorld(o, d, tmin, tmax, t);
  }
  Vec3 primitiveNormal(unsigned, const Vec3& worldPoint) const { return worldNormal(worldPoint); }
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
