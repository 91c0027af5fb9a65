#pragma once
// The barbule array seen in its cross-section plane (the plane normal to the barbule axis t).
//
// 2D coordinates: u along the vane normal n, v along x (across the barbules); angles are
// measured from u toward v, so a 3D direction (x, y, z) projects to the 2D direction
// (z, x) / |(z, x)| at azimuth gamma = atan2(x, z). One barbule is an ellipse with semi-axis b
// along its own u axis and 1 along its own v axis, turned by mu; in its own ("local") frame a
// point at normal angle phi is (b^2 cos phi, sin phi) / sqrt(b^2 cos^2 phi + sin^2 phi). Or,
// with an exponent p > 2, the superellipse |u / b|^p + |v|^p = 1 (barbule/superellipse.h): the
// ellipse's closed forms below are its p = 2 case, and each has a general counterpart. Only
// normals phi in (phi0, phi1) belong to the reflective, film-coated arc. Its neighbours are the
// same profile shifted by (0, +-H); they shadow and mask the central one.
//
// Seen along a direction d, the profile's lit side is parametrised by the offset h of the ray
// across d (h = p . across, across = d turned by +90 degrees); h grows monotonically with the
// normal angle over the lit side (the profile is convex), so every set of lit points below is an
// interval of offsets.
#include <optional>
#include "barbule/superellipse.h"
#include "core/fast_math.h"
#include "core/vector.h"

namespace columba {

inline float cross2(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline float dot2(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

// The part of the central barbule's reflective arc that a 2D direction reaches (lit: facing
// it and not shadowed by a neighbour), in the ellipse's local frame.
struct LitArc {
  Vec2 toward;                     // unit direction toward the light (local frame)
  Vec2 across;                     // `toward` turned by +90 degrees: the axis of the offsets h
  float halfWidth = 0.0f;          // the whole ellipse's silhouette spans offsets [-halfWidth, halfWidth]
  float hMin = 0.0f, hMax = 0.0f;  // offsets of the lit part; empty when hMax <= hMin
  // Front intersection of the ray at offset h on the ellipse: s = (-q h + sqrt(a - h^2 / b^2)) / a.
  float a = 1.0f, invA = 1.0f, q = 0.0f;

  float width() const { return hMax > hMin ? hMax - hMin : 0.0f; }
};

// Offsets [lo, hi] (empty when hi <= lo).
struct OffsetInterval {
  float lo = 0.0f, hi = 0.0f;
  float length() const { return hi > lo ? hi - lo : 0.0f; }
};

// The largest superellipse exponent taken: along the diagonal the profile then reaches 2^(-1/16),
// 96 % of the way to its bounding rectangle's corner.
inline constexpr float kMaxProfileExponent = 16.0f;

class BarbuleCrossSection {
 public:
  // phi1 - phi0 must lie in (0, pi] (the arc faces any direction in one piece) or be >= 2 pi (the
  // whole profile reflects). H below the contact spacing would make neighbours interpenetrate;
  // it is raised to it (barbules packed edge to edge). `exponent` p: 2 for the ellipse, more for
  // a superellipse (at most kMaxProfileExponent).
  BarbuleCrossSection(float b, float phi0, float phi1, float mu, float H, float exponent = 2.0f);
  // The same barbule (b and arc) with another tilt and spacing: a feather's per-point values. Costs
  // one sine and cosine, where building from scratch costs five.
  BarbuleCrossSection withTiltAndSpacing(float mu, float H) const;

  // Smallest spacing at which two neighbouring profiles do not overlap: translates K and K + w of
  // a centrally symmetric convex K overlap iff w/2 lies inside K.
  static float contactSpacing(float b, float mu, float exponent = 2.0f);

  float b() const { return b_; }
  bool isEllipse() const { return ellipse_; }
  const Superellipse& profile() const { return profile_; }
  float spacing() const { return H_; }
  // Local offset of the neighbour at +H (the one at -H is at minus it).
  Vec2 neighbourOffset() const { return neighbour_; }

  Vec2 toLocal(Vec2 w) const { return {w.x * cosMu_ + w.y * sinMu_, -w.x * sinMu_ + w.y * cosMu_}; }
  Vec2 toWorld(Vec2 l) const { return {l.x * cosMu_ - l.y * sinMu_, l.x * sinMu_ + l.y * cosMu_}; }

  // Lit part of the reflective arc for the unit world direction `toward` (either side of the vane).
  LitArc litArc(Vec2 toward) const;
  // Fraction of the projected barbule period H |cos gamma| that the lit arc covers, in [0, 1].
  float coverage(const LitArc& arc, Vec2 toward) const;

  // Point (local) where the ray at offset h coming along -toward first meets the central ellipse;
  // h must lie within [-halfWidth, halfWidth].
  Vec2 pointAt(const LitArc& arc, float h) const;
  // World normals toWorld(normalAt(p)) at four front points p at once (a quadrature's nodes), the
  // points parametrised by psi in [-pi/2, pi/2], h = halfWidth sin(psi): the angle of the point
  // once the ellipse is mapped to the unit circle. The point moves smoothly with psi where it
  // moves like sqrt(h) with h, at the silhouette.
  Vec2Lanes worldNormalsAtAngles(const LitArc& arc, FloatLanes sinPsi, FloatLanes cosPsi) const;
  // World normals toWorld(normalAt(pointAt(arc, h))) at four offsets at once, the same arithmetic
  // in lanes.
  Vec2Lanes worldNormalsAtOffsets(const LitArc& arc, FloatLanes h) const;
  // Unit outward normal (local) of the central profile at a point on it.
  Vec2 normalAt(Vec2 localPoint) const;
  // Point (local) of the central profile whose outward normal is the local unit vector n.
  Vec2 pointWithNormal(Vec2 n) const;
  // Offset along `arc` of the point with local unit normal n.
  float offsetOf(const LitArc& arc, Vec2 n) const { return dot2(pointWithNormal(n), arc.across); }
  // Whether the point with local unit normal n is lit along `arc`'s direction (masking and
  // shadowing test: it faces the direction, lies on the reflective arc and no neighbour blocks it).
  bool isLit(const LitArc& arc, Vec2 n) const;
  // The same for a point p already known with its normal n: on a superellipse's flat side the
  // normal, known to float precision, does not fix the point (docs/model.md).
  bool isLitAt(const LitArc& arc, Vec2 p, Vec2 n) const;
  // Offsets along `a` of the points lit along both `a` and `b`.
  OffsetInterval commonOffsets(const LitArc& a, const LitArc& b) const;

  // Radius of curvature at the point with local unit normal n: b^2 (n_v^2 + b^2 n_u^2)^(-3/2).
  float radiusOfCurvature(Vec2 n) const;
  bool onReflectiveArc(Vec2 n) const;

  // Nearest hit t > 0 of the world-space 2D ray origin + t dir (dir unit) with the central profile.
  std::optional<float> intersect(Vec2 origin, Vec2 dir) const;

 private:
  // World normals at offsets h whose sqrt(a - h^2 / b^2) (pointAt's square root) is `root`.
  Vec2Lanes worldNormalsAt(const LitArc& arc, FloatLanes h, FloatLanes root) const;
  static Vec2 normalize2(Vec2 v) {
    float inv = 1.0f / std::sqrt(v.x * v.x + v.y * v.y);
    return {v.x * inv, v.y * inv};
  }

  // Sets mu and H and what follows from them.
  void setTiltAndSpacing(float mu, float H);

  float b_, bSqr_, invBSqr_, H_;
  Superellipse profile_;
  bool ellipse_;  // exponent 2: the closed forms
  float cosMu_, sinMu_;
  Vec2 neighbour_;  // local offset of the neighbour at +H
  // The normal of the line separating the central profile from the neighbour at +H, which lies
  // on its positive side: the profile's normal in the neighbour's direction.
  Vec2 separatingNormal_;
  bool wholeProfile_;
  Vec2 arcStartNormal_, arcEndNormal_;  // local normals at phi0 and phi1
  Vec2 arcStartPoint_, arcEndPoint_;
};

}  // namespace columba
