#include "barbule/armed_cross_section.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/math.h"

namespace columba {

namespace {

double dot(Vec2d a, Vec2d b) { return a.x * b.x + a.y * b.y; }
Vec2d plus(Vec2d a, Vec2d b) { return {a.x + b.x, a.y + b.y}; }
Vec2d minus(Vec2d a, Vec2d b) { return {a.x - b.x, a.y - b.y}; }
Vec2d scaled(Vec2d a, double s) { return {a.x * s, a.y * s}; }
Vec2d normalized(Vec2d a) { return scaled(a, 1.0 / std::hypot(a.x, a.y)); }
// d turned by +90 degrees: the axis of the offsets of lines along d.
Vec2d across(Vec2d d) { return {-d.y, d.x}; }

// Outline points sampled per arm when looking for two arms' crossings, and the depth tolerance
// under which a point counts as on an occluder's outline rather than behind it.
constexpr int kCrossingSamples = 4096;
constexpr double kDepthTolerance = 1e-9;

}  // namespace

ArmedCrossSection::ArmedCrossSection(const std::vector<double>& tiltsRad, double b, double p, double mu, double H)
    : shape_(b, p) {
  if (tiltsRad.empty() || tiltsRad.size() > size_t(kMaxBarbuleArms))
    throw std::invalid_argument("a cross-section takes 1 to " + std::to_string(kMaxBarbuleArms) + " arms");
  for (double tilt : tiltsRad)
    if (!(std::abs(tilt) <= kMaxArmTilt))
      throw std::invalid_argument("an arm's tilt must lie between -89 and 89 degrees");
  if (!std::isfinite(mu) || !(H >= 0.0) || !std::isfinite(H))
    throw std::invalid_argument("the cross-section needs a finite tilt mu and a finite spacing H >= 0");
  if (!(b >= kMinArmSemiAxis && b <= kMaxArmSemiAxis))
    throw std::invalid_argument("an arm's semi-axis b must lie between 1e-4 and 100");
  // The chain's centre line: each arm's long axis is its face normal turned by +90 degrees, and
  // the next arm starts where this one ends. Centred on the midpoint of its two ends, then tilted.
  std::vector<Vec2d> centres;
  Vec2d end{0.0, 0.0}, start{0.0, 0.0};
  for (size_t k = 0; k < tiltsRad.size(); ++k) {
    const Vec2d axis{-std::sin(tiltsRad[k]), std::cos(tiltsRad[k])};
    if (k == 0) start = minus(end, axis);
    const Vec2d centre = k == 0 ? end : plus(end, axis);
    centres.push_back(centre);
    end = plus(centre, axis);
  }
  const Vec2d middle = scaled(plus(start, end), 0.5);
  const double cosMu = std::cos(mu), sinMu = std::sin(mu);
  for (size_t k = 0; k < tiltsRad.size(); ++k) {
    const Vec2d c = minus(centres[k], middle);
    Arm arm;
    arm.centre = {c.x * cosMu - c.y * sinMu, c.x * sinMu + c.y * cosMu};
    arm.cosTilt = std::cos(tiltsRad[k] + mu);
    arm.sinTilt = std::sin(tiltsRad[k] + mu);
    // Translates of a centrally symmetric convex outline along w are separated by the tangent
    // line at its point in w's direction, shifted by w / 2.
    const Vec2d w = toLocal(arm, {0.0, 1.0});
    const Vec2d radial = scaled(w, shape_.radialDistance(w));
    arm.separatingNormal = toWorld(arm, normalized(shape_.gradient(radial)));
    arms_.push_back(arm);
  }

  // Contact: arm b shifted by (0, t) overlaps arm a for t in an interval, whose top is the least
  // over normals n with n_v > 0 of the difference body's support over n_v (a 1D minimum: a grid,
  // then golden sections about its best node).
  contact_ = 0.0;
  auto support = [&](const Arm& arm, Vec2d n) { return dot(arm.centre, n) + shape_.support(toLocal(arm, n)); };
  for (const Arm& a : arms_)
    for (const Arm& bArm : arms_) {
      auto difference = [&](Vec2d n) { return support(a, n) + support(bArm, scaled(n, -1.0)); };
      // The vertical line through the origin must cross the difference body at all.
      if (difference({0.0, 1.0}) < 0.0 || difference({1.0, 0.0}) < 0.0 || difference({-1.0, 0.0}) < 0.0) continue;
      auto top = [&](double phi) {
        const Vec2d n{std::cos(phi), std::sin(phi)};
        return difference(n) / n.y;
      };
      constexpr int kNodes = 2000;
      const double step = kPiDouble / kNodes;
      double bestPhi = 0.5 * kPiDouble, best = top(bestPhi);
      for (int i = 1; i < kNodes; ++i)
        if (const double value = top(i * step); value < best) best = value, bestPhi = i * step;
      double lo = std::max(bestPhi - step, 1e-9), hi = std::min(bestPhi + step, kPiDouble - 1e-9);
      const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
      for (int i = 0; i < 80; ++i) {
        const double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
        if (top(x1) < top(x2))
          hi = x2;
        else
          lo = x1;
      }
      contact_ = std::max(contact_, std::min(best, top(0.5 * (lo + hi))));
    }
  H_ = std::max(H, contact_);

  // Crossings of two arms' outlines, by the sign of one's implicit function along the other.
  for (size_t a = 0; a < arms_.size(); ++a)
    for (size_t c = a + 1; c < arms_.size(); ++c) {
      auto at = [&](double angle) {
        const Vec2d dir{std::cos(angle), std::sin(angle)};
        return plus(arms_[a].centre, toWorld(arms_[a], scaled(dir, shape_.radialDistance(dir))));
      };
      auto inside = [&](double angle) {
        return shape_.implicit(toLocal(arms_[c], minus(at(angle), arms_[c].centre))) - 1.0;
      };
      const double step = 2.0 * kPiDouble / kCrossingSamples;
      for (int i = 0; i < kCrossingSamples; ++i) {
        double lo = i * step, hi = (i + 1) * step;
        const double fLo = inside(lo);
        if ((fLo < 0.0) == (inside(hi) < 0.0)) continue;
        for (int k = 0; k < 60; ++k) {
          const double mid = 0.5 * (lo + hi);
          ((inside(mid) < 0.0) == (fLo < 0.0) ? lo : hi) = mid;
        }
        crossings_.push_back(at(0.5 * (lo + hi)));
      }
    }
}

ArmedCrossSection::Shadow ArmedCrossSection::shadowOf(const Arm& arm, Vec2d d) const {
  const Vec2d e = across(d);
  return {dot(arm.centre, e), shape_.support(toLocal(arm, e)), H_ * e.y, dot(d, arm.separatingNormal) > 0.0};
}

std::optional<double> ArmedCrossSection::translateMet(const Shadow& shadow, double h) {
  if (shadow.shift == 0.0) return std::nullopt;
  // Translates k with centre + k shift - halfWidth <= h <= centre + k shift + halfWidth.
  const double a = (h - shadow.centre - shadow.halfWidth) / shadow.shift,
               c = (h - shadow.centre + shadow.halfWidth) / shadow.shift;
  const double kLo = std::ceil(std::min(a, c)), kHi = std::floor(std::max(a, c));
  if (kLo > kHi) return std::nullopt;
  return shadow.lightAbove ? kHi : kLo;
}

std::optional<ArmedCrossSection::Candidate> ArmedCrossSection::candidate(int armIndex, Vec2d d, double h) const {
  const Arm& arm = arms_[size_t(armIndex)];
  const Shadow shadow = shadowOf(arm, d);
  const std::optional<double> k = translateMet(shadow, h);
  if (!k) return std::nullopt;
  Candidate met;
  const Vec2d dLocal = toLocal(arm, d);
  met.localPoint = shape_.pointAtOffset(dLocal, h - shadow.centre - *k * shadow.shift);
  met.depth = dot(arm.centre, d) + *k * H_ * d.y + dot(met.localPoint, dLocal);
  return met;
}

bool ArmedCrossSection::ownNeighbourShadows(int armIndex, Vec2d d, double h) const {
  const Shadow shadow = shadowOf(arms_[size_t(armIndex)], d);
  if (shadow.shift == 0.0) return true;
  const double neighbour = shadow.centre + (shadow.lightAbove ? 1.0 : -1.0) * shadow.shift;
  return std::abs(h - neighbour) <= shadow.halfWidth;
}

std::optional<ArmHit> ArmedCrossSection::firstHit(Vec2d d, double h) const {
  std::optional<Candidate> best;
  int bestArm = 0;
  for (int a = 0; a < armCount(); ++a)
    if (std::optional<Candidate> c = candidate(a, d, h); c && (!best || c->depth > best->depth)) best = c, bestArm = a;
  if (!best) return std::nullopt;
  const Arm& arm = arms_[size_t(bestArm)];
  ArmHit hit;
  hit.arm = bestArm;
  hit.point = plus(arm.centre, toWorld(arm, best->localPoint));
  const Vec2d gradient = shape_.gradient(best->localPoint);
  hit.normal = toWorld(arm, normalized(gradient));
  hit.coated = gradient.x > 0.0;
  return hit;
}

bool ArmedCrossSection::isReached(int armIndex, Vec2d p, Vec2d d) const {
  const double h = dot(p, across(d)), depth = dot(p, d);
  if (ownNeighbourShadows(armIndex, d, h)) return false;
  for (int a = 0; a < armCount(); ++a) {
    if (a == armIndex) continue;
    if (std::optional<Candidate> c = candidate(a, d, h); c && c->depth > depth + kDepthTolerance) return false;
  }
  return true;
}

double ArmedCrossSection::coverage(Vec2d d) const {
  const Vec2d e = across(d);
  const double period = std::abs(H_ * e.y);
  if (!(period > 0.0)) return 0.0;
  // Each arm's shadow along d, and the offsets of its coated side that face d: the facing half and
  // the coated half of a convex outline meet in one arc, whose offsets run counter-clockwise from
  // the tip (0, -1), or the silhouette where that tip faces away, to the tip (0, 1) or the other
  // silhouette (as BarbuleCrossSection::litArc bounds its arc).
  struct View {
    Shadow shadow;
    double coatedLo, coatedHi;  // relative to the shadow's centre
  };
  std::array<View, kMaxBarbuleArms> views{};
  std::vector<double> events;
  events.reserve(4 * arms_.size() + crossings_.size() + 1);
  auto add = [&](double offset) { events.push_back(offset - period * std::floor(offset / period)); };
  for (size_t a = 0; a < arms_.size(); ++a) {
    const Vec2d dLocal = toLocal(arms_[a], d);
    const double tip = dLocal.x;  // the tip (0, 1)'s offset from the centre; (0, -1)'s is minus it
    View& v = views[a];
    v.shadow = shadowOf(arms_[a], d);
    const bool upperTipFaces = dLocal.y > 0.0, lowerTipFaces = dLocal.y < 0.0;
    v.coatedLo = lowerTipFaces ? -tip : -v.shadow.halfWidth;
    v.coatedHi = upperTipFaces ? tip : v.shadow.halfWidth;
    if (!lowerTipFaces && !upperTipFaces && !(dLocal.x > 0.0)) v.coatedLo = v.coatedHi = 0.0;
    add(v.shadow.centre + v.shadow.halfWidth);
    add(v.shadow.centre - v.shadow.halfWidth);
    // The tips, where the coated side ends.
    add(v.shadow.centre - tip);
    add(v.shadow.centre + tip);
  }
  for (const Vec2d& x : crossings_) add(dot(x, e));
  std::sort(events.begin(), events.end());
  events.push_back(events.front() + period);
  double lit = 0.0;
  for (size_t i = 0; i + 1 < events.size(); ++i) {
    const double length = events[i + 1] - events[i];
    if (!(length > 0.0)) continue;
    const double h = events[i] + 0.5 * length;
    // Where the shadows of one arm's translates alone hold the line, the line meets the one on the
    // light's side (translateMet), and the offset relative to it says whether on its coated side;
    // where several arms' shadows do, their entry points decide.
    int holding = 0;
    double relative = 0.0;
    const View* only = nullptr;
    for (size_t a = 0; a < arms_.size(); ++a) {
      const std::optional<double> k = translateMet(views[a].shadow, h);
      if (!k) continue;
      ++holding;
      relative = h - views[a].shadow.centre - *k * views[a].shadow.shift;
      only = &views[a];
    }
    if (holding == 0) continue;
    if (holding == 1) {
      if (relative >= only->coatedLo && relative <= only->coatedHi) lit += length;
      continue;
    }
    std::optional<ArmHit> hit = firstHit(d, h);
    if (hit && hit->coated) lit += length;
  }
  return std::clamp(lit / period, 0.0, 1.0);
}

ArmPoints ArmedCrossSection::pointsWithNormal(Vec2d n) const {
  ArmPoints points;
  for (int a = 0; a < armCount(); ++a) {
    const Arm& arm = arms_[size_t(a)];
    const Vec2d local = toLocal(arm, n);
    if (!(local.x > 0.0)) continue;
    const Vec2d x = shape_.pointWithNormal(local);
    points.points[size_t(points.count++)] = {a, plus(arm.centre, toWorld(arm, x)), shape_.radiusOfCurvature(local)};
  }
  return points;
}

}  // namespace columba
