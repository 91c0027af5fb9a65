#pragma once
// Which longitudinal normal angles theta at one point of the barbule's cross-section send omega_i's
// mirror reflection out unblocked (DESIGN.md §5.6). The R lobe samples theta only among those, so
// that its samples are not lost where a neighbouring barbule masks the reflected direction.
//
// At the point with local in-plane normal n (unit) the normal with longitudinal angle theta is
// m = (cos(theta) n, sin(theta)) and omega_i's mirror direction about it has the in-plane part
//   v(a) = a n - w,  a(theta) = 2 cos(theta) (A cos(theta) + B sin(theta)) = A + R cos(2 theta - delta),
// with w omega_i's in-plane part, A = w . n, B = omega_i's component along the barbule, R = |(A, B)|
// and delta = atan2(B, A). The point is lit along v (BarbuleCrossSection::isLit) when it faces v,
// n . v = a - A > 0, and the ray from it along v misses both neighbours: for a neighbour centred at
// c, with e = p - c and the ellipse's metric Q = diag(1 / b^2, 1), the ray meets it when
//   (e Q v)^2 >= (v Q v) (e Q e - 1)  and  e Q v < 0,
// a quadratic and a linear condition in a. On a superellipse (BarbuleCrossSection::isEllipse()
// false) the ray meets a neighbour when v lies between the two tangents from p to it, two linear
// conditions in a. So the visible values of a are bounded by at most seven numbers, each of which a(theta) crosses at most twice over the normals' range: the visible
// angles are a few intervals, found exactly, and the mass of theta's density on them is the
// density's primitive at their ends.
#include <array>
#include <optional>
#include "barbule/cross_section.h"
#include "barbule/normals.h"

namespace columba {

class MirrorVisibleAngles {
 public:
  // omega_i (w.z > 0) and the point with local in-plane normal `localNormal` on its lit arc:
  // `point` where it is known (on a superellipse's flat side the normal does not fix it), else
  // the one the normal gives.
  MirrorVisibleAngles(const BarbuleCrossSection& geometry, Vec2 localNormal, const Vec3& w,
                      std::optional<Vec2> point = std::nullopt);

  // The share of theta's density (LongitudinalDensity: proportional to omega_i . m) on the visible
  // angles: 1 where no neighbour masks the mirror direction, 0 where every angle is masked.
  float visibleFraction() const { return visibleMass_ > 0.0f && mass_ > 0.0f ? visibleMass_ / mass_ : 0.0f; }
  // theta drawn from that density restricted to the visible angles (visibleFraction() > 0), with
  // its cosine and sine.
  AngleCosSin sample(float u) const;
  // The world in-plane normal this was built with.
  Vec2 worldNormal() const { return worldNormal_; }

 private:
  // Whether the point is lit along the mirror direction with this value of a.
  bool visibleAt(double a) const;

  static constexpr int kMaxIntervals = 8;
  struct Interval {
    float lo, hi, massBelow;  // theta range and the density's mass on the intervals before it
  };
  Vec2 worldNormal_;
  LongitudinalDensity longitudinal_;
  float A_, B_;
  // The neighbours' conditions for meeting the ray: on the ellipse a^2 q2 - 2 a q1 + q0 >= 0 and
  // a alpha < beta; on a superellipse a start1 >= start0 and a end1 >= end0 (cross(D1, v) >= 0 and
  // cross(v, D2) >= 0 for its tangent directions D1, D2).
  bool ellipse_ = true;
  std::array<double, 2> q2_{}, q1_{}, q0_{}, alpha_{}, beta_{};
  struct Cone {
    double start1, start0, end1, end0;
  };
  std::array<Cone, 2> cone_{};
  std::array<Interval, kMaxIntervals> intervals_{};
  int intervalCount_ = 0;
  float mass_ = 0.0f, visibleMass_ = 0.0f;
};

}  // namespace columba
