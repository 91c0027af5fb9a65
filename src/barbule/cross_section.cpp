#include "barbule/cross_section.h"

#include <algorithm>
#include <stdexcept>

namespace columba {

namespace {
Vec2 toFloat(Vec2d v) { return {float(v.x), float(v.y)}; }
// The superellipse of a cross-section, after its parameters are checked.
Superellipse checkedProfile(float b, float exponent) {
  if (!(b > 0.0f)) throw std::invalid_argument("the barbule cross-section needs b > 0");
  if (!(exponent >= 2.0f && exponent <= kMaxProfileExponent))
    throw std::invalid_argument("the cross-section's exponent must lie in [2, 16]");
  return Superellipse(b, exponent);
}
}  // namespace

BarbuleCrossSection::BarbuleCrossSection(float b, float phi0, float phi1, float mu, float H, float exponent)
    : b_(b), bSqr_(b * b), invBSqr_(1.0f / (b * b)), profile_(checkedProfile(b, exponent)), ellipse_(exponent == 2.0f) {
  float arcWidth = phi1 - phi0;
  if (!(arcWidth > 0.0f && (arcWidth <= kPi + 1e-6f || arcWidth >= kTwoPi)))
    throw std::invalid_argument("the reflective arc phi_1 - phi_0 must lie in (0, pi] or cover the whole profile");
  setTiltAndSpacing(mu, H);
  wholeProfile_ = arcWidth >= kTwoPi;
  arcStartNormal_ = {std::cos(phi0), std::sin(phi0)};
  arcEndNormal_ = {std::cos(phi1), std::sin(phi1)};
  arcStartPoint_ = pointWithNormal(arcStartNormal_);
  arcEndPoint_ = pointWithNormal(arcEndNormal_);
}

namespace {
// The neighbour's offset (0, H) in the local frame is H (sin mu, cos mu); its half lies on the
// ellipse when (H/2)^2 (sin^2 mu / b^2 + cos^2 mu) = 1, on a superellipse at its radial distance.
float contactSpacingOf(float cosMu, float sinMu, float invBSqr, const Superellipse& profile, bool ellipse) {
  if (ellipse) return 2.0f / std::sqrt(sinMu * sinMu * invBSqr + cosMu * cosMu);
  return float(2.0 * profile.radialDistance({sinMu, cosMu}));
}
}  // namespace

float BarbuleCrossSection::contactSpacing(float b, float mu, float exponent) {
  return contactSpacingOf(std::cos(mu), std::sin(mu), 1.0f / (b * b), checkedProfile(b, exponent), exponent == 2.0f);
}

void BarbuleCrossSection::setTiltAndSpacing(float mu, float H) {
  cosMu_ = std::cos(mu);
  sinMu_ = std::sin(mu);
  H_ = std::max(H, contactSpacingOf(cosMu_, sinMu_, invBSqr_, profile_, ellipse_));
  neighbour_ = toLocal({0.0f, H_});
  // The gradient's direction is the same all along the ray from the centre (F is homogeneous).
  // The ellipse has its own test (litArc).
  if (!ellipse_) {
    // Normalised in double: the gradient's components overflow a float for thin profiles.
    const Vec2d g = profile_.gradient(toDouble(neighbour_));
    const double length = std::hypot(g.x, g.y);
    separatingNormal_ = {float(g.x / length), float(g.y / length)};
  }
}

BarbuleCrossSection BarbuleCrossSection::withTiltAndSpacing(float mu, float H) const {
  // The arc's normals and points live in the ellipse's own frame: only the tilt and spacing change.
  BarbuleCrossSection tilted = *this;
  tilted.setTiltAndSpacing(mu, H);
  return tilted;
}

Vec2 BarbuleCrossSection::normalAt(Vec2 localPoint) const {
  if (ellipse_) return normalize2({localPoint.x * invBSqr_, localPoint.y});
  Vec2d g = profile_.gradient(toDouble(localPoint));
  double length = std::hypot(g.x, g.y);
  return {float(g.x / length), float(g.y / length)};
}

Vec2 BarbuleCrossSection::pointWithNormal(Vec2 n) const {
  if (!ellipse_) return toFloat(profile_.pointWithNormal(toDouble(n)));
  float inv = 1.0f / std::sqrt(bSqr_ * n.x * n.x + n.y * n.y);
  return {bSqr_ * n.x * inv, n.y * inv};
}

float BarbuleCrossSection::radiusOfCurvature(Vec2 n) const {
  if (!ellipse_) return float(profile_.radiusOfCurvature(toDouble(n)));
  float s = n.y * n.y + bSqr_ * n.x * n.x;
  return bSqr_ / (s * std::sqrt(s));
}

bool BarbuleCrossSection::onReflectiveArc(Vec2 n) const {
  if (wholeProfile_) return true;
  // An arc of at most pi: n lies counter-clockwise from its start and clockwise from its end.
  return cross2(arcStartNormal_, n) >= 0.0f && cross2(n, arcEndNormal_) >= 0.0f;
}

LitArc BarbuleCrossSection::litArc(Vec2 towardWorld) const {
  LitArc arc;
  Vec2 d = toLocal(towardWorld);
  arc.toward = d;
  arc.across = {-d.y, d.x};
  arc.a = d.x * d.x * invBSqr_ + d.y * d.y;
  arc.invA = 1.0f / arc.a;
  arc.q = arc.across.x * d.x * invBSqr_ + arc.across.y * d.y;
  // Support of the profile along `across`: sqrt(b^2 across_u^2 + across_v^2) on the ellipse.
  arc.halfWidth = ellipse_ ? std::sqrt(d.x * d.x + bSqr_ * d.y * d.y) : float(profile_.support(toDouble(arc.across)));

  // Reflective arc within the lit (facing) half, whose offsets run from -halfWidth to halfWidth
  // counter-clockwise; an arc endpoint that does not face d is replaced by the silhouette it
  // leaves the facing half through.
  float lo, hi;
  if (wholeProfile_) {
    lo = -arc.halfWidth;
    hi = arc.halfWidth;
  } else {
    bool startFaces = dot2(arcStartNormal_, d) > 0.0f, endFaces = dot2(arcEndNormal_, d) > 0.0f;
    if (!startFaces && !endFaces) {
      // An arc of at most pi with both ends on the far side misses the facing half entirely.
      arc.hMin = arc.hMax = 0.0f;
      return arc;
    }
    lo = startFaces ? dot2(arcStartPoint_, arc.across) : -arc.halfWidth;
    hi = endFaces ? dot2(arcEndPoint_, arc.across) : arc.halfWidth;
  }

  // Shadowing. Neighbours do not overlap the central profile, so along every line crossing two of
  // them one is wholly in front: the one at +H when it lies further along d than the line
  // separating the two (separatingNormal . d > 0); the one at -H is then behind. On the ellipse
  // the same test reads: chord centres lie on the line s = -(q / a) h, so that neighbour (shifted
  // by c across and sigma along d) is in front iff sigma + (q / a) c > 0. The front neighbour
  // hides the offsets where its silhouette overlaps ours.
  float c = dot2(neighbour_, arc.across), sigma = dot2(neighbour_, d);
  bool plusInFront = ellipse_ ? sigma + arc.q * arc.invA * c > 0.0f : dot2(separatingNormal_, d) > 0.0f;
  float shift = plusInFront ? c : -c;
  if (shift > 0.0f)
    hi = std::min(hi, shift - arc.halfWidth);
  else
    lo = std::max(lo, shift + arc.halfWidth);

  arc.hMin = lo;
  arc.hMax = hi;
  return arc;
}

float BarbuleCrossSection::coverage(const LitArc& arc, Vec2 towardWorld) const {
  float period = H_ * std::abs(towardWorld.x);
  float width = arc.width();
  if (!(width > 0.0f) || !(period > 0.0f)) return 0.0f;
  return std::min(width / period, 1.0f);
}

Vec2 BarbuleCrossSection::pointAt(const LitArc& arc, float h) const {
  if (!ellipse_) return toFloat(profile_.pointAtOffset(toDouble(arc.toward), h));
  float root = std::sqrt(std::max(arc.a - h * h * invBSqr_, 0.0f));
  float s = (root - arc.q * h) * arc.invA;
  return arc.across * h + arc.toward * s;
}

Vec2Lanes BarbuleCrossSection::worldNormalsAtOffsets(const LitArc& arc, FloatLanes h) const {
  if (!ellipse_) {
    Vec2Lanes n;
    for (int j = 0; j < kLaneCount; ++j) {
      Vec2 world = toWorld(normalAt(pointAt(arc, h[j])));
      n.x[j] = world.x;
      n.y[j] = world.y;
    }
    return n;
  }
  FloatLanes underRoot = arc.a - h * h * invBSqr_;
  return worldNormalsAt(arc, h, sqrtLanes(underRoot < 0.0f ? FloatLanes{} : underRoot));
}

Vec2Lanes BarbuleCrossSection::worldNormalsAt(const LitArc& arc, FloatLanes h, FloatLanes root) const {
  // pointAt's front intersection s and normalAt's normalisation, then toWorld.
  FloatLanes s = (root - arc.q * h) * arc.invA;
  FloatLanes nx = (arc.across.x * h + arc.toward.x * s) * invBSqr_, ny = arc.across.y * h + arc.toward.y * s;
  FloatLanes inv = 1.0f / sqrtLanes(nx * nx + ny * ny);
  nx *= inv;
  ny *= inv;
  return {nx * cosMu_ - ny * sinMu_, nx * sinMu_ + ny * cosMu_};
}

Vec2Lanes BarbuleCrossSection::worldNormalsAtAngles(const LitArc& arc, FloatLanes sinPsi, FloatLanes cosPsi) const {
  if (!ellipse_) return worldNormalsAtOffsets(arc, arc.halfWidth * sinPsi);
  // With h = halfWidth sin(psi) and halfWidth^2 = b^2 a, sqrt(a - h^2 / b^2) = (halfWidth / b) cos(psi).
  return worldNormalsAt(arc, arc.halfWidth * sinPsi, arc.halfWidth / b_ * cosPsi);
}

bool BarbuleCrossSection::isLit(const LitArc& arc, Vec2 n) const { return isLitAt(arc, pointWithNormal(n), n); }

bool BarbuleCrossSection::isLitAt(const LitArc& arc, Vec2 p, Vec2 n) const {
  if (!(dot2(n, arc.toward) > 0.0f)) return false;
  float h = dot2(p, arc.across);
  return h >= arc.hMin && h <= arc.hMax;
}

OffsetInterval BarbuleCrossSection::commonOffsets(const LitArc& a, const LitArc& b) const {
  OffsetInterval out;
  if (!(a.width() > 0.0f) || !(b.width() > 0.0f)) return out;
  // b's lit points form an arc from pointAt(b, hMin) counter-clockwise to pointAt(b, hMax), of
  // less than pi in normal angle: its part on a's facing half is one piece, bounded by b's ends
  // where they face a and by a's silhouette where they do not.
  Vec2 start = pointAt(b, b.hMin), end = pointAt(b, b.hMax);
  // Facing tests need only the direction of the normal, (x / b^2, y) on the ellipse.
  bool startFaces =
      ellipse_ ? start.x * invBSqr_ * a.toward.x + start.y * a.toward.y > 0.0f : dot2(normalAt(start), a.toward) > 0.0f;
  bool endFaces =
      ellipse_ ? end.x * invBSqr_ * a.toward.x + end.y * a.toward.y > 0.0f : dot2(normalAt(end), a.toward) > 0.0f;
  if (!startFaces && !endFaces) return out;
  out.lo = std::max(a.hMin, startFaces ? dot2(start, a.across) : -a.halfWidth);
  out.hi = std::min(a.hMax, endFaces ? dot2(end, a.across) : a.halfWidth);
  return out;
}

std::optional<float> BarbuleCrossSection::intersect(Vec2 origin, Vec2 dir) const {
  Vec2 o = toLocal(origin), d = toLocal(dir);
  if (!ellipse_) {
    std::optional<double> t = profile_.intersect(toDouble(o), toDouble(d));
    return t ? std::optional<float>(float(*t)) : std::nullopt;
  }
  float A = d.x * d.x * invBSqr_ + d.y * d.y;
  float B = o.x * d.x * invBSqr_ + o.y * d.y;
  float C = o.x * o.x * invBSqr_ + o.y * o.y - 1.0f;
  float disc = B * B - A * C;
  if (disc < 0.0f) return std::nullopt;
  float root = std::sqrt(disc);
  // Stable roots of A t^2 + 2 B t + C = 0.
  float qq = -(B + std::copysign(root, B));
  float t0 = qq / A, t1 = qq != 0.0f ? C / qq : t0;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > 0.0f) return t0;
  if (t1 > 0.0f) return t1;
  return std::nullopt;
}

}  // namespace columba
