#pragma once
// A barbule cross-section's profile beyond the ellipse: the superellipse |u / b|^p + |v|^p = 1
// with p >= 2 (docs/model.md, "Cross-sections beyond the ellipse"). p = 2 is the paper's ellipse;
// as p grows the sides flatten and the profile tends to a b x 1 rectangle with rounded corners.
// It stays convex and centrally symmetric, which is what the lit-arc construction of
// BarbuleCrossSection needs; its normals, support and curvature have closed forms through the
// conjugate exponent q = p / (p - 1), and only the point a ray meets (pointAt) and the tangents
// from an outside point need a numeric solve. Everything here is in double precision: the powers
// lose digits near the flat sides.
#include <cmath>
#include <optional>

#include "core/vector.h"

namespace columba {

struct Vec2d {
  double x = 0.0, y = 0.0;
};
inline Vec2d toDouble(Vec2 v) { return {v.x, v.y}; }

class Superellipse {
 public:
  Superellipse(double b, double p);

  // F(x) = |x_u / b|^p + |x_v|^p: 1 on the profile, below 1 inside.
  double implicit(Vec2d x) const;
  // The outward normal direction (not normalised) at a point x: F's gradient over p.
  Vec2d gradient(Vec2d x) const;
  // Support function h(n) = max over the profile of x . n = (|b n_u|^q + |n_v|^q)^(1 / q).
  double support(Vec2d n) const;
  // The point with outward unit normal n: the support function's gradient.
  Vec2d pointWithNormal(Vec2d n) const;
  // Radius of curvature at the point with unit normal n, capped at kMaxRadiusOfCurvature: it is
  // infinite where a flat side's normal points along an axis (p > 2), an integrable singularity
  // of the normal distribution that no finite sample reaches.
  double radiusOfCurvature(Vec2d n) const;
  // Distance from the centre to the profile along the unit direction d.
  double radialDistance(Vec2d d) const { return std::pow(implicit(d), -1.0 / p_); }

  // The point where the line at offset h along e = d turned by +90 degrees (h clamped to
  // +-support(e)), coming from far along the unit direction d, first meets the profile.
  Vec2d pointAtOffset(Vec2d d, double h) const;
  // The two points where lines from the outside point e touch the profile, ordered so that the
  // rays from e meeting it are those between (first - e) and (second - e) counter-clockwise.
  // Where e lies on the profile (or inside it by rounding) the two are e's tangent line's
  // directions from e, the half-plane facing the profile.
  struct Tangents {
    Vec2d first, second;
  };
  Tangents tangentPoints(Vec2d e) const;
  // Nearest t > 0 with F(origin + t dir) = 1, if the ray meets the profile.
  std::optional<double> intersect(Vec2d origin, Vec2d dir) const;

  static constexpr double kMaxRadiusOfCurvature = 1e12;

 private:
  double b_, p_, q_;
};

}  // namespace columba
