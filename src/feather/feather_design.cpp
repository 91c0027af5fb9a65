#include "feather/feather_design.h"

namespace columba {

namespace {

Vec2 rotate(Vec2 v, float angle) {
  float c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

float attachment(const FeatherDesign& d, int index) {
  return d.bareBase + (1.0f - d.bareBase) * (float(index) + 0.5f) / float(d.barbsPerSide);
}

float meanBarbAngle(const FeatherDesign& d) { return 0.5f * (d.barbAngleBase + d.barbAngleTip) - 0.5f * d.barbCurl; }

}  // namespace

float vaneHalfWidth(const FeatherDesign& design, float t) {
  if (t <= 0.0f || t >= 1.0f) return 0.0f;
  // Rises quickly from the base, widest near 40%, rounded at the tip.
  return 0.5f * design.width * std::sqrt(std::sin(kPi * std::pow(t, 0.7f)));
}

Vec2 rachisPoint(const FeatherDesign& design, float t) {
  return {t * design.length, design.rachisBend * design.length * t * t};
}

Vec2 rachisDirection(const FeatherDesign& design, float t) {
  Vec2 d(1.0f, 2.0f * design.rachisBend * t);
  float len = std::sqrt(d.x * d.x + d.y * d.y);
  return {d.x / len, d.y / len};
}

std::array<Vec2, kBarbVertices> barbPolyline(const FeatherDesign& design, int side, int index, float lengthScale,
                                             float angleOffset) {
  const float t = attachment(design, index);
  const float angle = lerp(t, design.barbAngleBase, design.barbAngleTip) + angleOffset;
  const float curl = design.barbCurl;
  // A barb of length l whose heading turns linearly from `angle` to `angle - curl` reaches
  // l * reach across the rachis and l * advance along it.
  const float reach = (std::cos(angle - curl) - std::cos(angle)) / curl;
  const float advance = (std::sin(angle) - std::sin(angle - curl)) / curl;
  // The barb ends on the outline, at the length where its reach equals the vane's half-width
  // where it ends (found by bisection: the reach grows with the length, the half-width
  // vanishes at the feather's tip).
  float lo = 0.0f, hi = (1.0f - t) * design.length / advance;
  for (int i = 0; i < 40; ++i) {
    float mid = 0.5f * (lo + hi);
    (reach * mid < vaneHalfWidth(design, t + mid * advance / design.length) ? lo : hi) = mid;
  }
  float len = std::max(lo, 0.03f * design.length) * lengthScale;

  const Vec2 dir = rachisDirection(design, t);
  const Vec2 normal(-dir.y * float(side), dir.x * float(side));
  Vec2 p = rachisPoint(design, t) + normal * design.rachisHalfWidth;
  std::array<Vec2, kBarbVertices> points;
  const float step = len / float(kBarbSegments);
  for (int k = 0; k < kBarbVertices; ++k) {
    points[k] = p;
    // Heading at the middle of the next segment, turning toward the tip.
    float heading = angle - curl * (float(k) + 0.5f) / float(kBarbSegments);
    p = p + rotate(dir, float(side) * heading) * step;
  }
  return points;
}

std::array<Vec2, kBarbVertices> rachisPolyline(const FeatherDesign& design) {
  std::array<Vec2, kBarbVertices> points;
  for (int k = 0; k < kBarbVertices; ++k) points[k] = rachisPoint(design, float(k) / float(kBarbSegments));
  return points;
}

int barbsToTile(const FeatherDesign& design, float barbWidth, float meanWidthFraction) {
  float along = (1.0f - design.bareBase) * design.length;
  return std::max(2, int(std::lround(along * std::sin(meanBarbAngle(design)) / (barbWidth * meanWidthFraction))));
}

float barbSpacing(const FeatherDesign& design) {
  return (1.0f - design.bareBase) * design.length / float(design.barbsPerSide) * std::sin(meanBarbAngle(design));
}

}  // namespace columba
