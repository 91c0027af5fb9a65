#include "shapes/barb_strip.h"

namespace columba {

namespace {
float maxAbsComponent(const Vec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }
}  // namespace

BarbStrip BarbStrip::fromSegment(const Vec3& p0, const Vec3& axis, float length, const Vec3* incoming,
                                 const Vec3* outgoing, const Vec3& n, const StripProfile& profile) {
  BarbStrip s;
  s.p0 = p0;
  s.axis = axis;
  s.length = length;
  s.n = n;
  s.b = cross(axis, n);
  s.startMitre = incoming ? mitreNormal(*incoming, axis) : axis;
  s.endMitre = outgoing ? mitreNormal(axis, *outgoing) : axis;
  s.radius = profile.radius;
  s.halfWidthStart = profile.halfWidthStart;
  s.halfWidthEnd = profile.halfWidthEnd;
  return s;
}

void BarbStrip::bounds(Vec3& lo, Vec3& hi) const {
  // Every cross-section of the strip is an arc of at most +-phi_max = asin(hw / R), hw the
  // wider end's half-width. The arc lies within the trapezoid of its chord, at depth `sag` below
  // the top line, and its end tangents, which meet the top line at +-R tan(phi_max / 2) =
  // hw R / (2 R - sag). The strip lies within the prism over that trapezoid cut by the two mitre
  // planes, so within the box of the prism's 8 corners.
  const float hw = std::max(halfWidthStart, halfWidthEnd);
  const float sag = radius - safeSqrt(radius * radius - hw * hw);
  const float topHalfWidth = hw * radius / (2.0f * radius - sag);
  const float sb = dot(startMitre, b), sn = dot(startMitre, n), sa = dot(startMitre, axis);
  const float eb = dot(endMitre, b), en = dot(endMitre, n), ea = dot(endMitre, axis);
  lo = Vec3(INFINITY, INFINITY, INFINITY);
  hi = -lo;
  for (int c = 0; c < 4; ++c) {
    const float y = (c & 2) ? 0.0f : -sag;  // relative to the top line
    const float x = ((c & 2) ? topHalfWidth : hw) * ((c & 1) ? 1.0f : -1.0f);
    const float zStart = -(x * sb + y * sn) / sa, zEnd = length - (x * eb + y * en) / ea;
    for (float z : {zStart, zEnd}) {
      Vec3 corner = p0 + b * x + n * y + axis * z;
      lo = minv(lo, corner);
      hi = maxv(hi, corner);
    }
  }
  // Room for the mitre slack of intersect().
  Vec3 pad = Vec3(1, 1, 1) * (1e-5f * (maxAbsComponent(p0) + radius + length));
  lo = lo - pad;
  hi = hi + pad;
}

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

bool PackedStrip::intersect(const StripProfile& profile, const Vec3& o, const Vec3& d, float tmin, float tmax,
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
  float oz = dot(rel, axis), dz = dot(d, axis);
  // Slack for the mitre planes: a few ulps of the coordinates the hit point was computed from.
  float slack = 1e-6f * (maxAbsComponent(p0) + std::abs(ox) + std::abs(oy) + std::abs(oz) + radius);
  for (float t : {tc - dt, tc + dt}) {
    if (t <= tmin) continue;
    if (t >= tmax) return false;
    float px = ox + t * dx, py = oy + t * dy, pz = oz + t * dz;
    if (py <= 0.0f) continue;  // the half of the cylinder away from the strip
    float axial = pz / length;
    if (std::abs(px) > profile.halfWidthAt(axial)) continue;
    float below = py - radius;  // height relative to the top line
    if (px * startMitre.x + below * startMitre.y + pz * startMitre.z < -slack) continue;
    if (px * endMitre.x + below * endMitre.y + (pz - length) * endMitre.z > slack) continue;
    hit.t = t;
    hit.axial = axial;
    hit.angle = std::atan2(px, py);
    hit.normal = normalize(b * px + n * py);
    return true;
  }
  return false;
}

}  // namespace columba
