#include "barbule/superellipse.h"

#include <algorithm>
#include <stdexcept>

#include "core/math.h"

namespace columba {

namespace {

double dot(Vec2d a, Vec2d b) { return a.x * b.x + a.y * b.y; }
double cross(Vec2d a, Vec2d b) { return a.x * b.y - a.y * b.x; }
Vec2d unitAt(double angle) { return {std::cos(angle), std::sin(angle)}; }
// |x|^k with the sign of x.
double signedPower(double x, double k) { return std::copysign(std::pow(std::abs(x), k), x); }

// A root of f in the bracket [lo, hi] (f rising across it where `rises`, falling otherwise) by
// Newton's method from `start`, bisecting instead where a step would leave the bracket or fail to
// halve the step before last (Newton can cycle about an inflection): at most 100 steps.
template <typename F, typename Slope>
double bracketedRoot(F f, Slope slope, double lo, double hi, bool rises, double start, double tolerance) {
  double x = start, step = std::abs(hi - lo), stepBefore = step;
  for (int i = 0; i < 100; ++i) {
    const double value = f(x);
    if (std::abs(value) <= tolerance) break;
    ((value < 0.0) == rises ? lo : hi) = x;
    if (std::abs(hi - lo) < 1e-15) break;
    double next = x - value / slope(x);
    if (!(next > std::min(lo, hi) && next < std::max(lo, hi)) || std::abs(next - x) > 0.5 * stepBefore)
      next = 0.5 * (lo + hi);
    stepBefore = step;
    step = std::abs(next - x);
    x = next;
  }
  return x;
}

}  // namespace

Superellipse::Superellipse(double b, double p) : b_(b), p_(p), q_(p / (p - 1.0)) {
  if (!(b > 0.0) || !(p >= 2.0))
    throw std::invalid_argument("a superellipse needs b > 0 and an exponent of at least 2");
}

double Superellipse::implicit(Vec2d x) const { return std::pow(std::abs(x.x / b_), p_) + std::pow(std::abs(x.y), p_); }

Vec2d Superellipse::gradient(Vec2d x) const {
  return {signedPower(x.x / b_, p_ - 1.0) / b_, signedPower(x.y, p_ - 1.0)};
}

double Superellipse::support(Vec2d n) const {
  return std::pow(std::pow(std::abs(b_ * n.x), q_) + std::pow(std::abs(n.y), q_), 1.0 / q_);
}

Vec2d Superellipse::pointWithNormal(Vec2d n) const {
  // The gradient of h(n) = (|b n_u|^q + |n_v|^q)^(1/q), which is homogeneous of degree 1.
  const double scale = std::pow(support(n), 1.0 - q_);
  return {b_ * signedPower(b_ * n.x, q_ - 1.0) * scale, signedPower(n.y, q_ - 1.0) * scale};
}

double Superellipse::radiusOfCurvature(Vec2d n) const {
  // The curvature of the level set F = 1 at the point: (F_uu F_v^2 + F_vv F_u^2) / |grad F|^3
  // (F_uv = 0), with F's derivatives divided by p.
  const Vec2d x = pointWithNormal(n);
  const double ax = std::abs(x.x), ay = std::abs(x.y), bp = std::pow(b_, p_);
  const double gu = std::pow(ax, p_ - 1.0) / bp, gv = std::pow(ay, p_ - 1.0);
  const double guu = (p_ - 1.0) * std::pow(ax, p_ - 2.0) / bp, gvv = (p_ - 1.0) * std::pow(ay, p_ - 2.0);
  const double norm = std::sqrt(gu * gu + gv * gv);
  const double curvature = (guu * gv * gv + gvv * gu * gu) / (norm * norm * norm);
  return curvature > 1.0 / kMaxRadiusOfCurvature ? 1.0 / curvature : kMaxRadiusOfCurvature;
}

Vec2d Superellipse::pointAtOffset(Vec2d d, double h) const {
  // Along the line x(s) = h e + s d, G(s) = F(x(s)) - 1 is convex: Newton's method from beyond the
  // profile (where the line leaves the b x 1 box around it, G >= 0) descends monotonically onto
  // the largest root, never past it. Where the line grazes the profile (h at the silhouette) the
  // root is nearly double and the convergence linear, so the steps are many but bounded; where
  // rounding makes it miss, a step passes the line's lowest F, and that lowest point (the
  // silhouette) is the answer. Solving for the normal angle instead is ill-conditioned: along a
  // flat side a whole stretch of offsets shares normals within 1e-30.
  const Vec2d e{-d.y, d.x};
  const double halfWidth = support(e);
  h = std::clamp(h, -halfWidth, halfWidth);
  auto at = [&](double s) { return Vec2d{h * e.x + s * d.x, h * e.y + s * d.y}; };
  // G + 1 and G' / p at s, from one power per coordinate.
  auto evaluate = [&](double s, double& value, double& slope) {
    const Vec2d x = at(s);
    const double u = std::abs(x.x / b_), v = std::abs(x.y);
    const double uPower = std::pow(u, p_ - 1.0), vPower = std::pow(v, p_ - 1.0);
    value = uPower * u + vPower * v;
    slope = std::copysign(uPower, x.x) / b_ * d.x + std::copysign(vPower, x.y) * d.y;
  };
  double s = support(d);  // beyond the profile along d; the box's exit is nearer where the line has one
  const double half[2] = {b_, 1.0}, origin[2] = {h * e.x, h * e.y}, along[2] = {d.x, d.y};
  for (int axis = 0; axis < 2; ++axis)
    if (along[axis] != 0.0) s = std::min(s, (std::copysign(half[axis], along[axis]) - origin[axis]) / along[axis]);
  double value, slope;
  evaluate(s, value, slope);
  for (int i = 0; i < 200; ++i) {
    if (!(value > 1.0) || !(slope > 0.0)) break;  // on the profile
    const double next = s - (value - 1.0) / (p_ * slope);
    double nextValue, nextSlope;
    evaluate(next, nextValue, nextSlope);
    if (!(nextSlope > 0.0)) {
      // Past the lowest F without meeting the profile: bisect for the lowest point.
      double lo = next, hi = s;
      for (int k = 0; k < 100; ++k) {
        const double mid = 0.5 * (lo + hi);
        evaluate(mid, nextValue, nextSlope);
        (nextSlope > 0.0 ? hi : lo) = mid;
      }
      return at(hi);
    }
    const double step = s - next;
    s = next;
    value = nextValue;
    slope = nextSlope;
    if (step <= 1e-10 * (std::abs(s) + 1.0)) break;  // well below float resolution
  }
  return at(s);
}

Superellipse::Tangents Superellipse::tangentPoints(Vec2d e) const {
  // A line with unit normal nu touches the profile with e on it where h(nu) = nu . e; the normals
  // with h(nu) < nu . e (the lines separating e from the profile) form one arc, which holds the
  // normal at the profile's point toward e. Its two ends are the tangents.
  Vec2d toward = gradient(e);
  const double length = std::hypot(toward.x, toward.y);
  toward = {toward.x / length, toward.y / length};
  auto f = [&](double phi) { return support(unitAt(phi)) - dot(unitAt(phi), e); };
  // f' = nu' . (x(nu) - e), nu' the normal turned by +90 degrees.
  auto slope = [&](double phi) {
    const Vec2d n = unitAt(phi), x = pointWithNormal(n);
    return -n.y * (x.x - e.x) + n.x * (x.y - e.y);
  };
  const double centre = std::atan2(toward.y, toward.x);
  Tangents t;
  if (!(f(centre) < 0.0)) {
    // On the profile: its tangent line, the profile on the side opposite its outward normal.
    const Vec2d along{-toward.y, toward.x};
    t.first = {e.x + along.x, e.y + along.y};
    t.second = {e.x - along.x, e.y - along.y};
    return t;
  }
  const double tolerance = 1e-13 * (std::abs(e.x) + std::abs(e.y) + 1.0);
  const double ccw = bracketedRoot(f, slope, centre, centre + kPiDouble, true, centre + 0.25 * kPiDouble, tolerance);
  const double cw = bracketedRoot(f, slope, centre - kPiDouble, centre, false, centre - 0.25 * kPiDouble, tolerance);
  t.first = pointWithNormal(unitAt(ccw));
  t.second = pointWithNormal(unitAt(cw));
  const Vec2d a{t.first.x - e.x, t.first.y - e.y}, b{t.second.x - e.x, t.second.y - e.y};
  if (cross(a, b) < 0.0) std::swap(t.first, t.second);
  return t;
}

std::optional<double> Superellipse::intersect(Vec2d origin, Vec2d dir) const {
  // The ray within the bounding box |u| <= b, |v| <= 1, where F along it is convex: its minimum
  // (where F' = grad F . dir changes sign), then the crossings of 1 on either side by bisection.
  double t0 = -1e300, t1 = 1e300;
  const double half[2] = {b_, 1.0}, o[2] = {origin.x, origin.y}, d[2] = {dir.x, dir.y};
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] == 0.0) {
      if (std::abs(o[axis]) > half[axis]) return std::nullopt;
      continue;
    }
    double a = (-half[axis] - o[axis]) / d[axis], b = (half[axis] - o[axis]) / d[axis];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (!(t0 < t1) || !(t1 > 0.0)) return std::nullopt;
  auto at = [&](double t) { return Vec2d{origin.x + t * dir.x, origin.y + t * dir.y}; };
  auto bisect = [&](double lo, double hi, auto&& below) {
    for (int step = 0; step < 100; ++step) {
      const double mid = 0.5 * (lo + hi);
      (below(mid) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double lowest = bisect(t0, t1, [&](double t) { return dot(gradient(at(t)), dir) < 0.0; });
  if (!(implicit(at(lowest)) <= 1.0)) return std::nullopt;
  const double entry = bisect(t0, lowest, [&](double t) { return implicit(at(t)) > 1.0; });
  if (entry > 0.0) return entry;
  const double exit = bisect(lowest, t1, [&](double t) { return implicit(at(t)) <= 1.0; });
  if (exit > 0.0) return exit;
  return std::nullopt;
}

}  // namespace columba
