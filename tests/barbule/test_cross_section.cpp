#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>
#include "barbule/cross_section.h"
#include "barbule/superellipse.h"
#include "core/rng.h"

using namespace columba;

namespace {

struct CrossSectionCase {
  float b, H, mu, phi0, phi1;
  float p = 2.0f;  // superellipse exponent
};

// The reference scenes' barbules, a rounder tilted one, one packed closer than its contact spacing
// (raised to it), a circle reflective all round, and a thin one with a wide arc reaching the back;
// then superellipses: the reference shape squarer (p 3 and 4), a rounded rectangle packed at its
// contact spacing (p 8), a rounded square reflective all round and a thin, nearly rectangular one
// (p 16).
const CrossSectionCase kCases[] = {
    {0.25f, 1.25f, -0.35f, -0.37f, 2.64f},
    {0.5f, 2.5f, 0.3f, -1.2f, 1.0f},
    {0.35f, 1.0f, 0.6f, -0.5f, 2.0f},
    {1.0f, 3.0f, 0.0f, -kPi, kPi},
    {0.2f, 1.6f, -0.8f, 0.5f, 3.5f},
    {0.25f, 1.25f, -0.35f, -0.37f, 2.64f, 3.0f},
    {0.25f, 1.25f, -0.35f, -0.37f, 2.64f, 4.0f},
    {0.35f, 1.0f, 0.6f, -0.5f, 2.0f, 8.0f},
    {1.0f, 3.0f, 0.0f, -kPi, kPi, 6.0f},
    {0.2f, 1.6f, -0.8f, 0.5f, 3.5f, 16.0f},
};

BarbuleCrossSection makeGeometry(const CrossSectionCase& c) {
  return BarbuleCrossSection(c.b, c.phi0, c.phi1, c.mu, c.H, c.p);
}

double implicitValue(const CrossSectionCase& c, double u, double v) {
  return std::pow(std::abs(u / c.b), c.p) + std::pow(std::abs(v), c.p);
}

// Entry and exit of the local ray o + t d (d unit) with the profile |u / b|^p + |v|^p = 1: the
// ellipse in closed form; a superellipse by golden-section search for the ray's lowest F (F is
// convex along it) and bisection either side.
std::optional<std::pair<double, double>> chord(const CrossSectionCase& c, double lx, double ly, double ldx,
                                               double ldy) {
  if (c.p == 2.0f) {
    double ib2 = 1.0 / (double(c.b) * c.b);
    double A = ldx * ldx * ib2 + ldy * ldy, B = lx * ldx * ib2 + ly * ldy, C = lx * lx * ib2 + ly * ly - 1.0;
    double disc = B * B - A * C;
    if (disc < 0) return std::nullopt;
    return std::make_pair((-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A);
  }
  // Within the circle about the b x 1 box, or not at all.
  double centre = -(lx * ldx + ly * ldy), reachSqr = double(c.b) * c.b + 1.0;
  double missSqr = sqr(lx + centre * ldx) + sqr(ly + centre * ldy);
  if (missSqr >= reachSqr) return std::nullopt;
  double reach = std::sqrt(reachSqr - missSqr);
  auto F = [&](double t) { return implicitValue(c, lx + t * ldx, ly + t * ldy); };
  double lo = centre - reach, hi = centre + reach;
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 90; ++i) {
    double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    (F(x1) < F(x2) ? hi : lo) = F(x1) < F(x2) ? x2 : x1;
  }
  double lowest = 0.5 * (lo + hi);
  if (!(F(lowest) < 1.0)) return std::nullopt;
  auto edge = [&](double from, double to) {
    for (int i = 0; i < 60; ++i) {
      double mid = 0.5 * (from + to);
      (F(mid) < 1.0 ? from : to) = mid;
    }
    return from;
  };
  return std::make_pair(edge(lowest, centre - reach), edge(lowest, centre + reach));
}

// An independent 2D ray caster in double precision: profiles with semi-axes b (u) and 1 (v),
// turned by mu, centred at (0, k H) for k = -1, 0, 1.
struct Hit {
  double t;
  int ellipse;         // -1, 0, 1
  double normalAngle;  // outward normal angle in the ellipse's own frame
};

std::optional<Hit> castRay(const CrossSectionCase& c, double H, double ox, double oy, double dx, double dy) {
  std::optional<Hit> best;
  double cm = std::cos(c.mu), sm = std::sin(c.mu);
  for (int k = -1; k <= 1; ++k) {
    // Into the ellipse's frame (rotate by -mu about its centre).
    double px = ox, py = oy - k * H;
    double lx = px * cm + py * sm, ly = -px * sm + py * cm;
    double ldx = dx * cm + dy * sm, ldy = -dx * sm + dy * cm;
    std::optional<std::pair<double, double>> ends = chord(c, lx, ly, ldx, ldy);
    if (!ends) continue;
    for (double t : {ends->first, ends->second}) {
      if (t <= 1e-9) continue;
      if (!best || t < best->t) {
        // The normal: F's gradient, (sgn(u) |u / b|^(p-1) / b, sgn(v) |v|^(p-1)).
        double hx = lx + t * ldx, hy = ly + t * ldy;
        double gu = std::copysign(std::pow(std::abs(hx / c.b), c.p - 1.0) / c.b, hx);
        double gv = std::copysign(std::pow(std::abs(hy), c.p - 1.0), hy);
        best = Hit{t, k, std::atan2(gv, gu)};
      }
      break;
    }
  }
  return best;
}

bool onArc(const CrossSectionCase& c, double phi) {
  if (c.phi1 - c.phi0 >= 2.0 * M_PI) return true;
  double x = std::fmod(phi - c.phi0, 2.0 * M_PI);
  if (x < 0) x += 2.0 * M_PI;
  return x < c.phi1 - c.phi0;
}

Vec2 unit(double angle) { return Vec2(float(std::cos(angle)), float(std::sin(angle))); }

}  // namespace

TEST(CrossSection, LitExtentAndCoverageMatchABruteForceRayCasterSlow) {
  int checked = 0;
  for (const CrossSectionCase& c : kCases) {
    // A superellipse's rays cost a search each: fewer of them, and tolerances to match.
    const int rays = c.p == 2.0f ? 40000 : 4000;
    const double range = 3.0, spacing = 2.0 * range / rays;
    BarbuleCrossSection geometry = makeGeometry(c);
    double H = geometry.spacing();
    for (int g = 0; g < 72; ++g) {
      double gamma = -M_PI + (g + 0.5) * (2.0 * M_PI / 72);  // both sides of the vane
      double dx = std::cos(gamma), dy = std::sin(gamma), ex = -dy, ey = dx;
      double lo = 1e9, hi = -1e9;
      int lit = 0;
      for (int i = 0; i < rays; ++i) {
        double h = -range + (i + 0.5) * spacing;
        std::optional<Hit> hit = castRay(c, H, h * ex + 10.0 * dx, h * ey + 10.0 * dy, -dx, -dy);
        if (hit && hit->ellipse == 0 && onArc(c, hit->normalAngle)) {
          lo = std::min(lo, h);
          hi = std::max(hi, h);
          ++lit;
        }
      }
      Vec2 toward = unit(gamma);
      LitArc arc = geometry.litArc(toward);
      SCOPED_TRACE("b " + std::to_string(c.b) + " mu " + std::to_string(c.mu) + " gamma " + std::to_string(gamma));
      if (lit == 0) {
        EXPECT_LE(arc.width(), 2.0 * spacing);
        continue;
      }
      // One interval: every ray between the extreme lit ones is lit.
      EXPECT_NEAR(lit * spacing, hi - lo + spacing, 2.0 * spacing);
      EXPECT_NEAR(arc.hMin, lo, spacing);
      EXPECT_NEAR(arc.hMax, hi, spacing);
      double period = H * std::abs(dx);
      EXPECT_NEAR(geometry.coverage(arc, toward), std::min(lit * spacing / period, 1.0), 2.0 * spacing / period);
      EXPECT_LE(geometry.coverage(arc, toward), 1.0f);
      ++checked;
    }
  }
  EXPECT_GT(checked, 200);
}

TEST(CrossSection, MaskingMatchesRayCastingFromThePoint) {
  PCG32 rng(17);
  int lit = 0, dark = 0;
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    double H = geometry.spacing();
    for (int i = 0; i < 20000; ++i) {
      double phi = 2.0 * M_PI * rng.nextDouble(), gamma = 2.0 * M_PI * rng.nextDouble();
      Vec2 n = unit(phi), toward = unit(gamma);
      LitArc arc = geometry.litArc(toward);
      // Skip points within a hair of a boundary of the lit set.
      Vec2 localToward = geometry.toLocal(toward);
      if (std::abs(dot2(n, localToward)) < 1e-3f) continue;
      if (std::abs(std::sin(phi - c.phi0)) < 1e-3 || std::abs(std::sin(phi - c.phi1)) < 1e-3) continue;
      float h = dot2(geometry.pointWithNormal(n), arc.across);
      if (std::abs(h - arc.hMin) < 1e-3f || std::abs(h - arc.hMax) < 1e-3f) continue;

      Vec2 p = geometry.toWorld(geometry.pointWithNormal(n));
      bool faces = dot2(n, localToward) > 0.0f;
      bool blocked =
          faces && castRay(c, H, p.x + 1e-5 * toward.x, p.y + 1e-5 * toward.y, toward.x, toward.y).has_value();
      bool expected = faces && onArc(c, phi) && !blocked;
      ASSERT_EQ(geometry.isLit(arc, n), expected) << "b " << c.b << " phi " << phi << " gamma " << gamma;
      (expected ? lit : dark) += 1;
    }
  }
  EXPECT_GT(lit, 10000);
  EXPECT_GT(dark, 10000);
}

TEST(CrossSection, RayEllipseIntersectionMatchesTheImplicitEquation) {
  PCG32 rng(23);
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int i = 0; i < 5000; ++i) {
      Vec2 origin(4.0f * rng.nextFloat() - 2.0f, 4.0f * rng.nextFloat() - 2.0f);
      Vec2 dir = unit(2.0 * M_PI * rng.nextDouble());
      std::optional<float> t = geometry.intersect(origin, dir);
      // The caster's central ellipse alone (neighbours out of reach).
      std::optional<Hit> expected = castRay(c, 1e6, origin.x, origin.y, dir.x, dir.y);
      ASSERT_EQ(t.has_value(), expected.has_value() && expected->ellipse == 0);
      if (!t) continue;
      EXPECT_NEAR(*t, expected->t, 1e-4);
      Vec2 local = geometry.toLocal(origin + dir * *t);
      EXPECT_NEAR(implicitValue(c, local.x, local.y), 1.0, 1e-4 * c.p);
    }
  }
}

TEST(CrossSection, PointsNormalsAndOffsetsAreConsistent) {
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int g = 0; g < 36; ++g) {
      Vec2 toward = unit(-M_PI + (g + 0.5) * (2.0 * M_PI / 36));
      LitArc arc = geometry.litArc(toward);
      for (int i = 0; i <= 50; ++i) {
        float h = -arc.halfWidth + 2.0f * arc.halfWidth * i / 50.0f;
        Vec2 p = geometry.pointAt(arc, h);
        EXPECT_NEAR(dot2(p, arc.across), h, 1e-5f);
        EXPECT_NEAR(implicitValue(c, p.x, p.y), 1.0, 1e-4 * c.p);
        Vec2 n = geometry.normalAt(p);
        EXPECT_GE(dot2(n, arc.toward), -1e-4f);  // the side the ray meets first faces it
        Vec2 back = geometry.pointWithNormal(n);
        EXPECT_NEAR(back.x, p.x, 2e-4f);
        EXPECT_NEAR(back.y, p.y, 2e-4f);
        // The ray through p along `toward` passes p at offset h.
        std::optional<float> t = geometry.intersect(geometry.toWorld(p) + toward * 5.0f, toward * -1.0f);
        if (std::abs(h) < 0.99f * arc.halfWidth) {
          ASSERT_TRUE(t.has_value());
          EXPECT_NEAR(*t, 5.0f, 1e-3f);
        }
      }
    }
  }
}

TEST(CrossSection, NormalsAtFourOffsetsAreTheOnesOfOneAtATime) {
  // The lanes do the same arithmetic as pointAt, normalAt and toWorld: equal to the last bit.
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int g = 0; g < 36; ++g) {
      LitArc arc = geometry.litArc(unit(-M_PI + (g + 0.5) * (2.0 * M_PI / 36)));
      for (int i = 0; i < 12; i += 4) {
        FloatLanes h;
        for (int j = 0; j < kLaneCount; ++j) h[j] = -arc.halfWidth + 2.0f * arc.halfWidth * float(i + j) / 11.0f;
        Vec2Lanes lanes = geometry.worldNormalsAtOffsets(arc, h);
        for (int j = 0; j < kLaneCount; ++j) {
          Vec2 n = geometry.toWorld(geometry.normalAt(geometry.pointAt(arc, h[j])));
          EXPECT_EQ(lanes.x[j], n.x);
          EXPECT_EQ(lanes.y[j], n.y);
        }
      }
    }
  }
}

TEST(CrossSection, ProjectedCurvatureIntegratesToTheLitWidthSlow) {
  // dh = rho(phi) cos(gamma - phi - mu) dphi: the identity behind D_phi = rho / H. On a superellipse
  // rho is infinite where the normal points along an axis (like |phi - axis|^(-(p-2)/(p-1))): each
  // quarter is integrated in s with phi = axis + (pi/2) s^3 (10 - 15 s + 6 s^2), whose derivative
  // vanishes like s^2 there, enough for p up to 4; steeper profiles are checked by
  // RadiusOfCurvatureIsHowFastThePointTurns.
  const int steps = 50000;
  for (const CrossSectionCase& c : kCases) {
    if (c.p > 4.0f) continue;
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int g = 0; g < 24; ++g) {
      Vec2 toward = unit(-M_PI + (g + 0.5) * (2.0 * M_PI / 24));
      LitArc arc = geometry.litArc(toward);
      double facing = 0.0, lit = 0.0;
      for (int quarter = 0; quarter < 4; ++quarter)
        for (int i = 0; i < steps; ++i) {
          double s = (i + 0.5) / steps;
          double phi = quarter * M_PI / 2 + M_PI / 2 * s * s * s * (10.0 - 15.0 * s + 6.0 * s * s);
          double dphi = M_PI / 2 * 30.0 * s * s * (1.0 - s) * (1.0 - s) / steps;
          Vec2 n = unit(phi);
          double projected = dot2(n, arc.toward);
          if (projected <= 0.0) continue;
          double dh = geometry.radiusOfCurvature(n) * projected * dphi;
          facing += dh;
          if (geometry.isLit(arc, n)) lit += dh;
        }
      SCOPED_TRACE("b " + std::to_string(c.b) + " p " + std::to_string(c.p) + " g " + std::to_string(g));
      EXPECT_NEAR(facing, 2.0 * arc.halfWidth, 1e-3);
      EXPECT_NEAR(lit, arc.width(), 1e-3);
    }
  }
}

TEST(CrossSection, RadiusOfCurvatureIsHowFastThePointTurns) {
  // rho = |d x(n) / d phi| for the point x(n) with normal angle phi, by central differences in
  // double precision, away from the axes (where rho grows without bound for p > 2).
  PCG32 rng(31);
  for (double p : {2.0, 3.0, 4.0, 8.0, 16.0})
    for (double b : {0.2, 0.35, 1.0}) {
      Superellipse profile(b, p);
      for (int i = 0; i < 2000; ++i) {
        double phi = 2.0 * M_PI * rng.nextDouble();
        if (std::abs(std::sin(2.0 * phi)) < 0.05) continue;
        const double eps = 1e-6;
        Vec2d a = profile.pointWithNormal({std::cos(phi - eps), std::sin(phi - eps)});
        Vec2d z = profile.pointWithNormal({std::cos(phi + eps), std::sin(phi + eps)});
        double expected = std::hypot(z.x - a.x, z.y - a.y) / (2.0 * eps);
        double rho = profile.radiusOfCurvature({std::cos(phi), std::sin(phi)});
        ASSERT_NEAR(rho, expected, 1e-5 * expected + 1e-8) << "p " << p << " b " << b << " phi " << phi;
        // The point lies on the profile, its normal is n, and its projection on n is the support.
        Vec2d x = profile.pointWithNormal({std::cos(phi), std::sin(phi)});
        EXPECT_NEAR(profile.implicit(x), 1.0, 1e-12);
        Vec2d g = profile.gradient(x);
        EXPECT_NEAR(std::atan2(g.y, g.x), std::atan2(std::sin(phi), std::cos(phi)), 1e-9);
        EXPECT_NEAR(x.x * std::cos(phi) + x.y * std::sin(phi), profile.support({std::cos(phi), std::sin(phi)}), 1e-12);
      }
    }
}

TEST(CrossSection, TheSuperellipseOfExponentTwoIsTheEllipse) {
  // The superellipse's general formulas against the ellipse's closed forms.
  for (float b : {0.25f, 0.6f})
    for (int i = 0; i < 64; ++i) {
      double phi = 2.0 * M_PI * (i + 0.5) / 64;
      Vec2d n{std::cos(phi), std::sin(phi)};
      Superellipse profile(b, 2.0);
      double bb = double(b) * b, s = std::sqrt(bb * n.x * n.x + n.y * n.y);
      Vec2d x = profile.pointWithNormal(n);
      EXPECT_NEAR(x.x, bb * n.x / s, 1e-12);
      EXPECT_NEAR(x.y, n.y / s, 1e-12);
      EXPECT_NEAR(profile.support(n), s, 1e-12);
      EXPECT_NEAR(profile.radiusOfCurvature(n), bb / (s * s * s), 1e-9);
    }
}

TEST(CrossSection, TangentsFromAPointBoundTheRaysThatMeetTheProfile) {
  // Rays from an outside point meet the profile exactly when they lie between its two tangents,
  // against the independent ray caster.
  PCG32 rng(37);
  int met = 0, missed = 0;
  for (const CrossSectionCase& c : kCases) {
    if (c.p == 2.0f) continue;
    Superellipse profile(c.b, c.p);
    CrossSectionCase alone = c;
    alone.mu = 0.0f;
    for (int i = 0; i < 400; ++i) {
      Vec2d e{4.0 * rng.nextDouble() - 2.0, 4.0 * rng.nextDouble() - 2.0};
      if (profile.implicit(e) < 1.02) continue;
      Superellipse::Tangents t = profile.tangentPoints(e);
      // The tangent points lie on the profile, the lines from e touch it there.
      EXPECT_NEAR(profile.implicit(t.first), 1.0, 1e-9);
      EXPECT_NEAR(profile.implicit(t.second), 1.0, 1e-9);
      Vec2d d1{t.first.x - e.x, t.first.y - e.y}, d2{t.second.x - e.x, t.second.y - e.y};
      for (int k = 0; k < 50; ++k) {
        double angle = 2.0 * M_PI * rng.nextDouble();
        Vec2d v{std::cos(angle), std::sin(angle)};
        bool between = d1.x * v.y - d1.y * v.x >= 0.0 && v.x * d2.y - v.y * d2.x >= 0.0;
        double a1 = std::atan2(d1.x * v.y - d1.y * v.x, d1.x * v.x + d1.y * v.y);
        double a2 = std::atan2(v.x * d2.y - v.y * d2.x, v.x * d2.x + v.y * d2.y);
        if (std::abs(a1) < 1e-4 || std::abs(a2) < 1e-4) continue;           // grazing
        std::optional<Hit> hit = castRay(alone, 1e15, e.x, e.y, v.x, v.y);  // neighbours out of reach
        ASSERT_EQ(between, hit.has_value()) << "p " << c.p << " e " << e.x << " " << e.y << " angle " << angle;
        (between ? met : missed) += 1;
      }
    }
  }
  EXPECT_GT(met, 2000);
  EXPECT_GT(missed, 20000);
}

TEST(CrossSection, CommonOffsetsAreThePointsLitFromBothDirections) {
  PCG32 rng(29);
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int i = 0; i < 400; ++i) {
      Vec2 a = unit(2.0 * M_PI * rng.nextDouble()), b = unit(2.0 * M_PI * rng.nextDouble());
      LitArc arcA = geometry.litArc(a), arcB = geometry.litArc(b);
      OffsetInterval common = geometry.commonOffsets(arcA, arcB);
      // Scan a's lit offsets.
      const int steps = 2000;
      double lo = 1e9, hi = -1e9, step = 2.0 * arcA.halfWidth / steps;
      for (int k = 0; k < steps; ++k) {
        float h = -arcA.halfWidth + (k + 0.5f) * float(step);
        if (h < arcA.hMin || h > arcA.hMax) continue;
        Vec2 n = geometry.normalAt(geometry.pointAt(arcA, h));
        if (geometry.isLit(arcB, n)) {
          lo = std::min<double>(lo, h);
          hi = std::max<double>(hi, h);
        }
      }
      if (lo > hi) {
        EXPECT_LE(common.length(), 2.0 * step);
      } else {
        EXPECT_NEAR(common.lo, lo, 1.5 * step);
        EXPECT_NEAR(common.hi, hi, 1.5 * step);
      }
    }
  }
}

TEST(CrossSection, NeighboursAreRaisedToTheContactSpacing) {
  float b = 0.35f, mu = 0.6f;
  float contact = BarbuleCrossSection::contactSpacing(b, mu);
  // Half the neighbour's offset lies on the ellipse: the two touch there.
  BarbuleCrossSection touching(b, -0.5f, 2.0f, mu, contact);
  Vec2 half = touching.toLocal({0.0f, 0.5f * contact});
  EXPECT_NEAR(sqr(half.x / b) + sqr(half.y), 1.0f, 1e-5f);
  EXPECT_EQ(BarbuleCrossSection(b, -0.5f, 2.0f, mu, 0.5f * contact).spacing(), contact);
  EXPECT_EQ(BarbuleCrossSection(b, -0.5f, 2.0f, mu, 2.0f * contact).spacing(), 2.0f * contact);
  EXPECT_THROW(BarbuleCrossSection(b, 0.0f, 4.0f, mu, 1.0f), std::invalid_argument);
  // A superellipse's contact: half the offset on its profile, |u / b|^p + |v|^p = 1.
  for (float p : {3.0f, 8.0f}) {
    float squareContact = BarbuleCrossSection::contactSpacing(b, mu, p);
    Vec2 squareHalf = BarbuleCrossSection(b, -0.5f, 2.0f, mu, 0.0f, p).toLocal({0.0f, 0.5f * squareContact});
    EXPECT_NEAR(std::pow(std::abs(squareHalf.x / b), p) + std::pow(std::abs(squareHalf.y), p), 1.0f, 1e-5f);
    EXPECT_GT(squareContact, contact);  // the squarer profile reaches further
  }
  EXPECT_THROW(BarbuleCrossSection(b, -0.5f, 2.0f, mu, 1.0f, 1.5f), std::invalid_argument);
  EXPECT_THROW(BarbuleCrossSection(b, -0.5f, 2.0f, mu, 1.0f, 17.0f), std::invalid_argument);
}
