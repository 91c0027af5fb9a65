#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>
#include "barbule/cross_section.h"
#include "core/rng.h"

using namespace columba;

namespace {

struct CrossSectionCase {
  float b, H, mu, phi0, phi1;
};

// The reference scenes' barbules, a rounder tilted one, one packed closer than its contact spacing
// (raised to it), a circle reflective all round, and a thin one with a wide arc reaching the back.
const CrossSectionCase kCases[] = {
    {0.25f, 1.25f, -0.35f, -0.37f, 2.64f}, {0.5f, 2.5f, 0.3f, -1.2f, 1.0f}, {0.35f, 1.0f, 0.6f, -0.5f, 2.0f},
    {1.0f, 3.0f, 0.0f, -kPi, kPi},         {0.2f, 1.6f, -0.8f, 0.5f, 3.5f},
};

BarbuleCrossSection makeGeometry(const CrossSectionCase& c) {
  return BarbuleCrossSection(c.b, c.phi0, c.phi1, c.mu, c.H);
}

// An independent 2D ray caster in double precision: ellipses with semi-axes b (u) and 1 (v),
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
    double ib2 = 1.0 / (double(c.b) * c.b);
    double A = ldx * ldx * ib2 + ldy * ldy, B = lx * ldx * ib2 + ly * ldy, C = lx * lx * ib2 + ly * ly - 1.0;
    double disc = B * B - A * C;
    if (disc < 0) continue;
    for (double t : {(-B - std::sqrt(disc)) / A, (-B + std::sqrt(disc)) / A}) {
      if (t <= 1e-9) continue;
      if (!best || t < best->t) {
        double hx = lx + t * ldx, hy = ly + t * ldy;
        best = Hit{t, k, std::atan2(hy, hx * ib2)};
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
  const int rays = 40000;
  const double range = 3.0, spacing = 2.0 * range / rays;
  int checked = 0;
  for (const CrossSectionCase& c : kCases) {
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
      EXPECT_NEAR(sqr(local.x / c.b) + sqr(local.y), 1.0f, 1e-4f);
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
        EXPECT_NEAR(sqr(p.x / c.b) + sqr(p.y), 1.0f, 1e-4f);
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
  // dh = rho(phi) cos(gamma - phi - mu) dphi: the identity behind D_phi = rho / H.
  const int steps = 200000;
  for (const CrossSectionCase& c : kCases) {
    BarbuleCrossSection geometry = makeGeometry(c);
    for (int g = 0; g < 24; ++g) {
      Vec2 toward = unit(-M_PI + (g + 0.5) * (2.0 * M_PI / 24));
      LitArc arc = geometry.litArc(toward);
      double facing = 0.0, lit = 0.0;
      for (int i = 0; i < steps; ++i) {
        Vec2 n = unit(2.0 * M_PI * (i + 0.5) / steps);
        double projected = dot2(n, arc.toward);
        if (projected <= 0.0) continue;
        double dh = geometry.radiusOfCurvature(n) * projected * (2.0 * M_PI / steps);
        facing += dh;
        if (geometry.isLit(arc, n)) lit += dh;
      }
      EXPECT_NEAR(facing, 2.0 * arc.halfWidth, 1e-3);
      EXPECT_NEAR(lit, arc.width(), 1e-3);
    }
  }
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
}
