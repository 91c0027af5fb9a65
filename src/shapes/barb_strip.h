#pragma once
// One segment of a barb polyline as a strip of a circular cylinder.
//
// The cylinder runs parallel to the segment; its top line is the segment itself and its axis
// lies `radius` below it along -n. The strip is the part of the cylinder within an angle
// |phi| <= phi_max around n (phi measured from n toward b = cross(axis, n)); phi_max shrinks
// along the segment as the barb tapers: the strip's half-width R sin(phi_max) is interpolated
// linearly between the two ends. Both ends are cut by mitre planes, the planes that bisect the
// angle between this segment and its neighbours (at a barb's first and last vertex the cut is
// square), so consecutive strips share the same cut curve: with the strip normals transported
// across each joint by reflection in the mitre plane (see transportAcrossJoint), the two
// cylinders are mirror images in that plane and meet without gap or overlap. The strip's outer
// edges are serrated (barb_serration.h): rays pass through the gaps between the teeth.
#include "core/vector.h"
#include "shapes/barb_serration.h"

namespace columba {

// Unit direction of the segment p0 -> p1. Strip axes and mitre planes are all derived from these
// directions, so neighbouring strips see bit-identical planes.
inline Vec3 segmentDirection(const Vec3& p0, const Vec3& p1) { return normalize(p1 - p0); }

// Normal of the plane bisecting the joint between an incoming and an outgoing unit direction,
// oriented along the barb.
inline Vec3 mitreNormal(const Vec3& incoming, const Vec3& outgoing) { return normalize(incoming + outgoing); }

// The strip normal of the next segment: the reflection of `n` in the joint's mitre plane. It is
// perpendicular to the next segment and makes the two cylinders mirror images in that plane.
inline Vec3 transportAcrossJoint(const Vec3& n, const Vec3& mitre) {
  return normalize(n - 2.0f * dot(n, mitre) * mitre);
}

inline float maxAbsComponent(const Vec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }

struct StripHit {
  float t = 0.0f;
  float axial = 0.0f;     // distance along the segment from its start vertex, divided by its length
  float sinAngle = 0.0f;  // sin(phi), phi the signed angle from n toward b (|phi| < pi/2); the
                          // normal and the angle follow from it (FeatherShape::interaction)
};

// The cross-section of a strip: the cylinder's radius and the strip's half-width R sin(phi_max)
// at both ends. Every barb tapers alike, so shapes keep one profile per segment index.
struct StripProfile {
  float radius = 0.0f;
  float halfWidthStart = 0.0f, halfWidthEnd = 0.0f;

  float halfWidthAt(float axial) const { return lerp(clampf(axial, 0.0f, 1.0f), halfWidthStart, halfWidthEnd); }
};

struct BarbStrip {
  Vec3 p0;    // start vertex (on the top line)
  Vec3 axis;  // unit direction toward the next vertex
  float length = 0.0f;
  Vec3 n, b;                  // strip normal at phi = 0 (outer side) and cross(axis, n)
  Vec3 startMitre, endMitre;  // unit normals of the end planes through p0 and p0 + length * axis
  float radius = 0.0f;
  float halfWidthStart = 0.0f, halfWidthEnd = 0.0f;  // R sin(phi_max) at both ends

  // The segment from `p0` along the unit direction `axis` for `length`, with strip normal `n`
  // (unit, perpendicular to `axis`) and end planes `startMitre` and `endMitre` (mitreNormal of
  // the joints; `axis` for the square cuts at a barb's first and last vertex).
  static BarbStrip fromSegment(const Vec3& p0, const Vec3& axis, float length, const Vec3& startMitre,
                               const Vec3& endMitre, const Vec3& n, const StripProfile& profile);

  StripProfile profile() const { return {radius, halfWidthStart, halfWidthEnd}; }
  // A box containing the strip (PackedStrip::bounds).
  void bounds(Vec3& lo, Vec3& hi) const;

  Vec3 point(float axial, float angle) const;
  Vec3 normal(float angle) const { return n * std::cos(angle) + b * std::sin(angle); }
  // Unit tangent of the cross-section circle at `angle`, toward increasing angle.
  Vec3 circumferential(float angle) const { return b * std::cos(angle) - n * std::sin(angle); }
};

// A BarbStrip as the intersector reads it, precomputed at load into one 64-byte cache line per
// segment: the radius and half-widths are the shape's (see StripProfile), b = cross(axis, n) is
// recomputed (bit-identical to BarbStrip::b), and the end planes are stored in the strip's own
// frame, where the intersector tests them.
struct alignas(64) PackedStrip {
  Vec3 p0;
  float length = 0.0f;
  Vec3 axis, n;
  Vec3 startMitre, endMitre;  // components along (b, n, axis) of BarbStrip's unit plane normals

  PackedStrip() = default;
  explicit PackedStrip(const BarbStrip& s);

  Vec3 b() const { return cross(axis, n); }

  // A box containing the strip, with room for the mitre slack of intersect().
  void bounds(const StripProfile& profile, Vec3& lo, Vec3& hi) const;

  // Nearest hit with t in (tmin, tmax) of the ray o + t d (d need not be unit), on the strip
  // less the gaps of its serrated edges. Points within a few float ulps of a mitre plane count
  // as inside on both sides, so rays through a joint cannot slip between the two strips; the
  // duplicate is at the same point. Inline: it is the body of the Embree intersect callback.
  bool intersect(const StripProfile& profile, const Vec3& o, const Vec3& d, float tmin, float tmax,
                 StripHit& hit) const;
};
static_assert(sizeof(PackedStrip) == 64, "a packed strip fills one cache line");

inline bool PackedStrip::intersect(const StripProfile& profile, const Vec3& o, const Vec3& d, float tmin, float tmax,
                                   StripHit& hit) const {
  const float radius = profile.radius;
  const Vec3 b = this->b();
  // Local coordinates: x along b, y along n with the cylinder axis at y = 0, z along the axis.
  Vec3 rel = o - p0;
  float ox = dot(rel, b), oy = dot(rel, n) + radius;
  float dx = dot(d, b), dy = dot(d, n);
  float a = dx * dx + dy * dy;
  if (!(a > 1e-12f * lengthSquared(d))) return false;  // parallel to the axis
  // Solve from the ray's point closest to the axis: this avoids the cancellation of the
  // textbook discriminant when the ray starts far from a thin cylinder.
  float tc = -(ox * dx + oy * dy) / a;
  float cx = ox + tc * dx, cy = oy + tc * dy;
  float gap = radius * radius - (cx * cx + cy * cy);
  if (gap < 0.0f) return false;
  float dt = std::sqrt(gap / a);
  // Rays leaving a neighbouring strip often cross this cylinder only behind their start.
  if (tc + dt <= tmin) return false;
  float oz = dot(rel, axis), dz = dot(d, axis);
  for (float t : {tc - dt, tc + dt}) {
    if (t <= tmin) continue;
    if (t >= tmax) return false;
    float px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
    if (py <= 0.0f) continue;  // the half of the cylinder away from the strip
    float axial = pz / length;
    const float halfWidth = profile.halfWidthAt(axial);
    if (std::abs(px) > halfWidth) continue;
    // Slack for the mitre planes: a few ulps of the coordinates the hit point was computed from.
    float slack = 1e-6f * (maxAbsComponent(p0) + std::abs(ox) + std::abs(oy) + std::abs(oz) + radius);
    float below = py - radius;  // height relative to the top line
    if (px * startMitre.x + below * startMitre.y + pz * startMitre.z < -slack) continue;
    if (px * endMitre.x + below * endMitre.y + (pz - length) * endMitre.z > slack) continue;
    // The angle and normal are left to the surviving hit: most are superseded by nearer ones.
    const float sinAngle = px * (1.0f / std::sqrt(px * px + py * py));
    if (!BarbSerration::keeps(std::abs(sinAngle), halfWidth / radius, axial)) continue;
    hit.t = t;
    hit.axial = axial;
    hit.sinAngle = sinAngle;
    return true;
  }
  return false;
}

}  // namespace columba
