#include "shapes/shape.h"

#include <stdexcept>

namespace columba {

namespace {
// Offset scaled to the position's magnitude, so spawned rays clear float round-off.
Vec3 offsetOrigin(const Vec3& p, const Vec3& ng, const Vec3& d) {
  float scale = 2e-5f * std::max(1e-2f, std::max(std::abs(p.x), std::max(std::abs(p.y), std::abs(p.z))));
  Vec3 off = ng * scale;
  return dot(d, ng) < 0.0f ? p - off : p + off;
}
}  // namespace

Ray SurfaceInteraction::spawnRay(const Vec3& d) const { return Ray{offsetOrigin(p, ng, d), d}; }

Ray SurfaceInteraction::spawnRayTo(const Vec3& target) const {
  Vec3 d = target - p;
  Ray r{offsetOrigin(p, ng, d), d};
  r.d = target - r.o;
  r.tmax = 1.0f - 1e-4f;
  return r;
}

float Shape::surfaceArea() const { throw std::logic_error("this shape cannot carry an area emitter"); }
PositionSample Shape::samplePosition(Vec2, bool) const {
  throw std::logic_error("this shape cannot carry an area emitter");
}

std::optional<ReferenceSample> Shape::sampleFrom(const Vec3& ref, Vec2 u, bool withTexturePoint) const {
  PositionSample ps = samplePosition(u, withTexturePoint);
  Vec3 d = ps.p - ref;
  float dist2 = lengthSquared(d);
  float cosLight = -dot(ps.n, d) / std::sqrt(dist2);
  if (dist2 == 0.0f || cosLight <= 0.0f) return std::nullopt;  // the point faces away
  return ReferenceSample{ps.p, ps.n, ps.point, ps.pdfArea * dist2 / cosLight};
}

float Shape::pdfFrom(const Vec3& ref, const SurfaceInteraction& hit) const {
  Vec3 d = hit.p - ref;
  float dist2 = lengthSquared(d);
  float cosLight = -dot(hit.ng, d) / std::sqrt(dist2);
  return cosLight > 0.0f ? dist2 / (cosLight * surfaceArea()) : 0.0f;
}

}  // namespace columba
