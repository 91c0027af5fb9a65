#include "barbule/mirror_visibility.h"

#include <algorithm>
#include <cmath>
#include "core/fast_math.h"
#include "core/math.h"

namespace columba {

namespace {
// x Q y with the ellipse's metric Q = diag(1 / b^2, 1), in which it is the unit circle.
double metric(Vec2 x, Vec2 y, double invBSqr) { return double(x.x) * y.x * invBSqr + double(x.y) * y.y; }
}  // namespace

MirrorVisibleAngles::MirrorVisibleAngles(const BarbuleCrossSection& geometry, Vec2 localNormal, const Vec3& w,
                                         std::optional<Vec2> point)
    : worldNormal_(geometry.toWorld(localNormal)),
      longitudinal_(inPlaneProjection(w, worldNormal_), w.y),
      A_(inPlaneProjection(w, worldNormal_)),
      B_(w.y) {
  mass_ = longitudinal_.mass();
  if (!(mass_ > 0.0f)) return;
  const double invBSqr = 1.0 / (double(geometry.b()) * geometry.b());
  const Vec2 p = point ? *point : geometry.pointWithNormal(localNormal);
  const Vec2 in = geometry.toLocal(Vec2(w.z, w.x));  // omega_i's in-plane part, of length cos(theta_i)
  const double nQn = metric(localNormal, localNormal, invBSqr), nQw = metric(localNormal, in, invBSqr);
  const double wQw = metric(in, in, invBSqr);

  // a(theta) = 2 cos(theta) (A cos(theta) + B sin(theta)) = A + R cos(2 theta - delta) over
  // [thetaMin, thetaMax]: its range there, from the ends and, where a' = 2 (B cos(2 theta) -
  // A sin(2 theta)) changes sign, its maximum A + R.
  const float thetaMin = longitudinal_.thetaMin(), thetaMax = longitudinal_.thetaMax();
  // At +-thetaD from the constants; at an end clipped where omega_i . m = 0, a = 0.
  auto aAt = [&](float theta) {
    if (std::abs(theta) != kBarbuleThetaD) return 0.0;
    const double sinTheta = std::copysign(double(kSinBarbuleThetaD), double(theta));
    return 2.0 * kCosBarbuleThetaD * (A_ * double(kCosBarbuleThetaD) + B_ * sinTheta);
  };
  // The sign of a' (B cos(2 theta) - A sin(2 theta)), from the constants at +-thetaD.
  auto slope = [&](float theta) {
    if (std::abs(theta) != kBarbuleThetaD) return B_ * std::cos(2.0 * theta) - A_ * std::sin(2.0 * theta);
    const double c = kCosBarbuleThetaD, sn = std::copysign(double(kSinBarbuleThetaD), double(theta));
    return B_ * (c * c - sn * sn) - A_ * 2.0 * sn * c;
  };
  const double R = std::sqrt(double(A_) * A_ + double(B_) * B_);
  const double aAtMin = aAt(thetaMin), aAtMax = aAt(thetaMax);
  const double aLo = std::min(aAtMin, aAtMax);
  const bool peakInside = slope(thetaMin) > 0.0 && slope(thetaMax) < 0.0;
  const double aHi = peakInside ? A_ + R : std::max(aAtMin, aAtMax);
  // The values of a where visibility can change: facing (a = A), and per neighbour where the ray
  // starts or stops meeting it (the quadratic's roots) and where e Q v changes sign.
  std::array<double, 7> bounds{};
  int boundCount = 0;
  bounds[boundCount++] = A_;
  ellipse_ = geometry.isEllipse();
  for (int side = 0; side < 2; ++side) {
    const Vec2 centre = side == 0 ? geometry.neighbourOffset() : geometry.neighbourOffset() * -1.0f;
    const Vec2 e = p - centre;
    if (!ellipse_) {
      // A superellipse: the rays from p meeting the neighbour are those between its two tangent
      // directions D1, D2 (counter-clockwise), cross(D1, v) >= 0 and cross(v, D2) >= 0, each
      // linear in a for v = a n - w.
      const Superellipse::Tangents t = geometry.profile().tangentPoints({e.x, e.y});
      const double d1x = t.first.x - e.x, d1y = t.first.y - e.y, d2x = t.second.x - e.x, d2y = t.second.y - e.y;
      cone_[side] = {d1x * localNormal.y - d1y * localNormal.x, d1x * in.y - d1y * in.x,
                     localNormal.x * d2y - localNormal.y * d2x, in.x * d2y - in.y * d2x};
      const Cone& c = cone_[side];
      if (c.start1 != 0.0) bounds[boundCount++] = c.start0 / c.start1;
      if (c.end1 != 0.0) bounds[boundCount++] = c.end0 / c.end1;
      continue;
    }
    const double K = metric(e, e, invBSqr) - 1.0;  // > 0: the point lies outside its neighbours
    alpha_[side] = metric(e, localNormal, invBSqr);
    beta_[side] = metric(e, in, invBSqr);
    // (a alpha - beta)^2 - K (v Q v) with v Q v = a^2 nQn - 2 a nQw + wQw.
    q2_[side] = alpha_[side] * alpha_[side] - K * nQn;
    q1_[side] = alpha_[side] * beta_[side] - K * nQw;
    q0_[side] = beta_[side] * beta_[side] - K * wQw;
    if (alpha_[side] != 0.0) bounds[boundCount++] = beta_[side] / alpha_[side];
    double r0, r1;
    // Only roots within (aLo, aHi) can cut the range: solved for only where the quadratic changes
    // sign over it or has its vertex inside (it usually has neither).
    auto f = [&](double a) { return (q2_[side] * a - 2.0 * q1_[side]) * a + q0_[side]; };
    const double vertex = q2_[side] != 0.0 ? q1_[side] / q2_[side] : aLo;  // aLo: a line has none inside
    const bool mayCut = f(aLo) * f(aHi) <= 0.0 || (vertex > aLo && vertex < aHi);
    if (mayCut && solveQuadratic(q2_[side], -2.0 * q1_[side], q0_[side], r0, r1)) {
      bounds[boundCount++] = r0;
      bounds[boundCount++] = r1;
    }
  }

  // Where a(theta) crosses a bound within the range. Usually none does (the range of theta is
  // narrow): then visibility is the same at every angle.
  std::array<float, 2 * 7 + 2> cuts{};
  int cutCount = 0;
  cuts[cutCount++] = thetaMin;
  double delta = 0.0;
  bool deltaKnown = false;
  for (int k = 0; k < boundCount; ++k) {
    if (!(bounds[k] > aLo && bounds[k] < aHi)) continue;
    if (!deltaKnown) {
      delta = std::atan2(double(B_), double(A_));
      deltaKnown = true;
    }
    const double half = std::acos(std::clamp((bounds[k] - A_) / R, -1.0, 1.0));
    for (double twoTheta : {delta + half, delta - half}) {
      // delta in (-pi/2, pi/2] (A > 0) and half in [0, pi]: one turn at most to take off.
      const double wrapped = twoTheta > kPiDouble     ? twoTheta - 2.0 * kPiDouble
                             : twoTheta <= -kPiDouble ? twoTheta + 2.0 * kPiDouble
                                                      : twoTheta;
      const float theta = float(0.5 * wrapped);
      if (theta > thetaMin && theta < thetaMax) cuts[cutCount++] = theta;
    }
  }
  std::sort(cuts.begin() + 1, cuts.begin() + cutCount);
  cuts[cutCount++] = thetaMax;

  // Visibility is constant between cuts: test each piece at its middle, merging neighbours.
  for (int k = 0; k + 1 < cutCount; ++k) {
    const float lo = cuts[k], hi = cuts[k + 1];
    if (!(hi > lo)) continue;
    // Away from the cuts: two terms of the series for |theta| <= thetaD suffice.
    float cosMid, sinMid;
    cosSinOfSmallAngle(0.5f * (lo + hi), cosMid, sinMid);
    if (!visibleAt(2.0 * cosMid * (A_ * cosMid + B_ * sinMid))) continue;
    if (intervalCount_ > 0 && intervals_[intervalCount_ - 1].hi == lo) {
      intervals_[intervalCount_ - 1].hi = hi;
    } else {
      intervals_[intervalCount_++] = {lo, hi, 0.0f};
    }
  }
  if (intervalCount_ == 1 && intervals_[0].lo == thetaMin && intervals_[0].hi == thetaMax) {
    visibleMass_ = mass_;  // every angle: the usual case, without evaluating the primitive
    return;
  }
  for (int k = 0; k < intervalCount_; ++k) {
    intervals_[k].massBelow = visibleMass_;
    visibleMass_ +=
        std::max(longitudinal_.massBelow(intervals_[k].hi) - longitudinal_.massBelow(intervals_[k].lo), 0.0f);
  }
}

bool MirrorVisibleAngles::visibleAt(double a) const {
  if (!(a > A_)) return false;  // facing away from the mirror direction
  for (int side = 0; side < 2; ++side) {
    const bool meets = ellipse_
                           ? (q2_[side] * a - 2.0 * q1_[side]) * a + q0_[side] >= 0.0 && a * alpha_[side] < beta_[side]
                           : a * cone_[side].start1 >= cone_[side].start0 && a * cone_[side].end1 >= cone_[side].end0;
    if (meets) return false;
  }
  return true;
}

AngleCosSin MirrorVisibleAngles::sample(float u) const {
  const float target = u * visibleMass_;
  int k = 0;
  while (k + 1 < intervalCount_ && intervals_[k + 1].massBelow <= target) ++k;
  const Interval& piece = intervals_[k];
  // Within the piece, the full range's inverse CDF at the mass below the target.
  AngleCosSin angle = longitudinal_.angleAtMass(longitudinal_.massBelow(piece.lo) + (target - piece.massBelow));
  if (!(angle.theta >= piece.lo && angle.theta <= piece.hi)) {
    // Past an end by rounding: at the end.
    angle.theta = clampf(angle.theta, piece.lo, piece.hi);
    angle.cosTheta = std::cos(angle.theta);
    angle.sinTheta = std::sin(angle.theta);
  }
  return angle;
}

}  // namespace columba
