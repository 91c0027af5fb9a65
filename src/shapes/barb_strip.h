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
// cylinders are mirror images in that plane and meet without gap or overlap.
#include "core/vector.h"

namespace columba {

// Unit direction of the segment p0 -> p1. Shared by the loader and the intersector so both see
// bit-identical mitre planes.
inline Vec3 segmentDirection(const Vec3& p0, const Vec3& p1) { return normalize(p1 - p0); }

// Normal of the plane bisecting the joint between an incoming and an outgoing unit direction,
// oriented along the barb.
inline Vec3 mitreNormal(const Vec3& incoming, const Vec3& outgoing) { return normalize(incoming + outgoing); }

// The strip normal of the next segment: the reflection of `n` in the joint's mitre plane. It is
// perpendicular to the next segment and makes the two cylinders mirror images in that plane.
inline Vec3 transportAcrossJoint(const Vec3& n, const Vec3& mitre) { return normalize(n - 2.0f * dot(n, mitre) * mitre); }

struct StripHit {
  float t = 0.0f;
  float axial = 0.0f;  // distance along the segment from its start vertex, divided by its length
  float angle = 0.0f;  // phi, the signed angle from n toward b
};

struct BarbStrip {
  Vec3 p0;             // start vertex (on the top line)
  Vec3 axis;           // unit direction toward the next vertex
  float length = 0.0f;
  Vec3 n, b;           // strip normal at phi = 0 (outer side) and cross(axis, n)
  Vec3 startMitre, endMitre;  // unit normals of the end planes through p0 and p0 + length * axis
  float radius = 0.0f;
  float halfWidthStart = 0.0f, halfWidthEnd = 0.0f;  // R sin(phi_max) at both ends

  // The segment from `points[i]` to `points[i + 1]` of a polyline with `count` points, with
  // strip normal `n` (unit, perpendicular to the segment).
  static BarbStrip fromPolyline(const Vec3* points, int count, int i, const Vec3& n, float radius,
                                float halfWidthStart, float halfWidthEnd);

  // Nearest hit with t in (tmin, tmax) of the ray o + t d (d need not be unit). Points within a
  // few float ulps of a mitre plane count as inside on both sides, so rays through a joint
  // cannot slip between the two strips; the duplicate is at the same point.
  bool intersect(const Vec3& o, const Vec3& d, float tmin, float tmax, StripHit& hit) const;

  // A box containing the strip.
  void bounds(Vec3& lo, Vec3& hi) const;

  Vec3 point(float axial, float angle) const;
  Vec3 normal(float angle) const { return n * std::cos(angle) + b * std::sin(angle); }
  // Unit tangent of the cross-section circle at `angle`, toward increasing angle.
  Vec3 circumferential(float angle) const { return b * std::cos(angle) - n * std::sin(angle); }
  float halfWidthAt(float axial) const { return lerp(clampf(axial, 0.0f, 1.0f), halfWidthStart, halfWidthEnd); }
};

}  // namespace columba
