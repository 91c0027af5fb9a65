#include "shapes/barb_strip.h"

namespace columba {

BarbStrip BarbStrip::fromSegment(const Vec3& p0, const Vec3& axis, float length, const Vec3& startMitre,
                                 const Vec3& endMitre, const Vec3& n, const StripProfile& profile) {
  BarbStrip s;
  s.p0 = p0;
  s.axis = axis;
  s.length = length;
  s.n = n;
  s.b = cross(axis, n);
  s.startMitre = startMitre;
  s.endMitre = endMitre;
  s.radius = profile.radius;
  s.halfWidthStart = profile.halfWidthStart;
  s.halfWidthEnd = profile.halfWidthEnd;
  return s;
}

void BarbStrip::bounds(Vec3& lo, Vec3& hi) const { PackedStrip(*this).bounds(profile(), lo, hi); }

Vec3 BarbStrip::point(float axial, float angle) const {
  return p0 + axis * (axial * length) + n * (radius * (std::cos(angle) - 1.0f)) + b * (radius * std::sin(angle));
}

PackedStrip::PackedStrip(const BarbStrip& s)
    : p0(s.p0),
      length(s.length),
      axis(s.axis),
      n(s.n),
      startMitre(dot(s.startMitre, s.b), dot(s.startMitre, s.n), dot(s.startMitre, s.axis)),
      endMitre(dot(s.endMitre, s.b), dot(s.endMitre, s.n), dot(s.endMitre, s.axis)) {}

void PackedStrip::bounds(const StripProfile& profile, Vec3& lo, Vec3& hi) const {
  // Every cross-section of the strip is an arc of at most +-phi_max = asin(hw / R), hw the
  // wider end's half-width. The arc lies within the trapezoid of its chord, at depth `sag` below
  // the top line, and its end tangents, which meet the top line at +-R tan(phi_max / 2) =
  // hw R / (2 R - sag). The strip lies within the prism over that trapezoid cut by the two mitre
  // planes, so within the box of the prism's 8 corners.
  const float radius = profile.radius;
  const float hw = std::max(profile.halfWidthStart, profile.halfWidthEnd);
  const float sag = radius - safeSqrt(radius * radius - hw * hw);
  const float topHalfWidth = hw * radius / (2.0f * radius - sag);
  const Vec3 b = this->b();
  lo = Vec3(INFINITY, INFINITY, INFINITY);
  hi = -lo;
  for (int c = 0; c < 4; ++c) {
    const float y = (c & 2) ? 0.0f : -sag;  // relative to the top line
    const float x = ((c & 2) ? topHalfWidth : hw) * ((c & 1) ? 1.0f : -1.0f);
    // Where the prism's edge through (x, y) meets the two end planes.
    const float zStart = -(x * startMitre.x + y * startMitre.y) / startMitre.z;
    const float zEnd = length - (x * endMitre.x + y * endMitre.y) / endMitre.z;
    const Vec3 edge = p0 + b * x + n * y;
    for (const Vec3& corner : {edge + axis * zStart, edge + axis * zEnd}) {
      lo = minv(lo, corner);
      hi = maxv(hi, corner);
    }
  }
  // Room for the mitre slack of intersect().
  Vec3 pad = Vec3(1, 1, 1) * (1e-5f * (maxAbsComponent(p0) + radius + length));
  lo = lo - pad;
  hi = hi + pad;
}

}  // namespace columba
