#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>
#include "barbule/armed_cross_section.h"
#include "barbule/cross_section.h"
#include "core/math.h"
#include "core/rng.h"

using namespace columba;

namespace {

struct ArmsCase {
  std::vector<double> tiltsDeg;
  double b, p, muDeg, H;
};

// A roof of three mirrors (the parotia's angles), the same as a valley, a V of two rounded arms
// tilted and packed at contact, a lopsided chain, and one arm (the paper's ellipse barbule).
const ArmsCase kCases[] = {
    {{-30.0, 0.0, 30.0}, 0.2, 8.0, 0.0, 7.0}, {{30.0, 0.0, -30.0}, 0.2, 8.0, 0.0, 7.0},
    {{40.0, -40.0}, 0.3, 2.0, 15.0, 0.0},     {{-60.0, 10.0, 45.0, -20.0}, 0.15, 4.0, -25.0, 9.0},
    {{0.0}, 0.25, 2.0, -20.0, 1.25},
};

double radians(double degrees) { return degrees * kPiDouble / 180.0; }

std::vector<double> tiltsOf(const ArmsCase& c) {
  std::vector<double> tilts;
  for (double t : c.tiltsDeg) tilts.push_back(radians(t));
  return tilts;
}

ArmedCrossSection makeGeometry(const ArmsCase& c) {
  return ArmedCrossSection(tiltsOf(c), c.b, c.p, radians(c.muDeg), c.H);
}

// The arm's frame: its tilt plus the cross-section's.
Vec2d toArm(const ArmsCase& c, int arm, Vec2d w) {
  const double angle = radians(c.tiltsDeg[size_t(arm)] + c.muDeg);
  return {w.x * std::cos(angle) + w.y * std::sin(angle), -w.x * std::sin(angle) + w.y * std::cos(angle)};
}

double implicit(const ArmsCase& c, Vec2d x) {
  return std::pow(std::abs(x.x / c.b), c.p) + std::pow(std::abs(x.y), c.p);
}

// Where the local line o + t d (d unit) enters the arm's outline, by its own search: F is convex
// along the line, so golden sections find its lowest point and bisection the entry before it.
std::optional<double> entry(const ArmsCase& c, Vec2d o, Vec2d d) {
  const double centre = -(o.x * d.x + o.y * d.y), reach = std::sqrt(c.b * c.b + 1.0);
  auto f = [&](double t) { return implicit(c, {o.x + t * d.x, o.y + t * d.y}); };
  double lo = centre - reach, hi = centre + reach;
  if (implicit(c, {o.x + centre * d.x, o.y + centre * d.y}) > 1.0 &&
      std::hypot(o.x + centre * d.x, o.y + centre * d.y) > reach)
    return std::nullopt;  // the line passes outside the circle about the arm's box
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 120; ++i) {
    const double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
    if (f(x1) < f(x2))
      hi = x2;
    else
      lo = x1;
  }
  const double lowest = 0.5 * (lo + hi);
  if (f(lowest) > 1.0) return std::nullopt;
  double a = centre - reach, b = lowest;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (a + b);
    (f(mid) > 1.0 ? a : b) = mid;
  }
  return 0.5 * (a + b);
}

struct BruteHit {
  int arm;
  Vec2d point;  // translated back to the central barbule
};

// The first arm the line at offset h from far along d meets, trying every arm of 61 barbules.
std::optional<BruteHit> bruteFirstHit(const ArmsCase& c, const ArmedCrossSection& g, Vec2d d, double h,
                                      double farAway = 400.0) {
  const Vec2d e{-d.y, d.x};
  const Vec2d origin{h * e.x + farAway * d.x, h * e.y + farAway * d.y};
  std::optional<BruteHit> best;
  double bestT = 1e300;
  for (int arm = 0; arm < g.armCount(); ++arm)
    for (int k = -30; k <= 30; ++k) {
      const Vec2d centre{g.armCentre(arm).x, g.armCentre(arm).y + k * g.spacing()};
      const Vec2d o = toArm(c, arm, {origin.x - centre.x, origin.y - centre.y});
      std::optional<double> t = entry(c, o, toArm(c, arm, {-d.x, -d.y}));
      if (t && *t < bestT) {
        bestT = *t;
        best = BruteHit{arm, {origin.x - *t * d.x, origin.y - *t * d.y - k * g.spacing()}};
      }
    }
  return best;
}

Vec2d unitAt(double angle) { return {std::cos(angle), std::sin(angle)}; }

// The share of `lines` lines spread evenly over one period seen along d whose first hit is coated.
double coatedShare(const ArmedCrossSection& g, Vec2d d, int lines) {
  const double period = std::abs(g.spacing() * d.x);
  int coated = 0;
  for (int j = 0; j < lines; ++j) {
    std::optional<ArmHit> hit = g.firstHit(d, (j + 0.5) / lines * period);
    if (hit && hit->coated) ++coated;
  }
  return double(coated) / lines;
}

}  // namespace

TEST(ArmedCrossSection, TheFirstArmMetIsTheOneEveryBarbuleTriedFindsFirst) {
  PCG32 rng(5);
  for (const ArmsCase& c : kCases) {
    const ArmedCrossSection g = makeGeometry(c);
    int hits = 0;
    for (int i = 0; i < 300; ++i) {
      // Directions from above and below, away from grazing the vane.
      const double angle = (rng.nextDouble() - 0.5) * 2.6 + (i % 2 ? kPiDouble : 0.0);
      const Vec2d d = unitAt(angle);
      const double h = rng.nextDouble() * 8.0 - 4.0;
      std::optional<ArmHit> hit = g.firstHit(d, h);
      std::optional<BruteHit> brute = bruteFirstHit(c, g, d, h);
      ASSERT_EQ(hit.has_value(), brute.has_value()) << "angle " << angle << " h " << h;
      if (!hit) continue;
      ++hits;
      EXPECT_NEAR(hit->point.x, brute->point.x, 1e-6);
      EXPECT_NEAR(hit->point.y, brute->point.y, 1e-6);
      // Where two arms' outlines cross the point is on both; elsewhere the arm must agree.
      if (std::hypot(hit->point.x - brute->point.x, hit->point.y - brute->point.y) < 1e-6 && hit->arm != brute->arm) {
        const Vec2d other =
            toArm(c, brute->arm, {hit->point.x - g.armCentre(brute->arm).x, hit->point.y - g.armCentre(brute->arm).y});
        EXPECT_NEAR(implicit(c, other), 1.0, 1e-5);
      }
      // The normal is the outline's, pointing back toward the light.
      EXPECT_GT(hit->normal.x * d.x + hit->normal.y * d.y, -1e-9);
    }
    EXPECT_GT(hits, 100);
  }
}

TEST(ArmedCrossSection, APointIsReachedExactlyWhereTheLineThroughItMeetsItFirst) {
  PCG32 rng(9);
  for (const ArmsCase& c : kCases) {
    const ArmedCrossSection g = makeGeometry(c);
    int reached = 0, blocked = 0;
    for (int i = 0; i < 400; ++i) {
      const Vec2d n = unitAt(rng.nextDouble() * 2.0 * kPiDouble);
      const ArmPoints points = g.pointsWithNormal(n);
      const double angle = (rng.nextDouble() - 0.5) * 2.6 + (i % 2 ? kPiDouble : 0.0);
      const Vec2d d = unitAt(angle);
      for (const ArmPoint& p : points) {
        if (n.x * d.x + n.y * d.y <= 0.05) continue;  // facing d, away from the silhouette
        const double h = -p.point.x * d.y + p.point.y * d.x;
        std::optional<BruteHit> brute = bruteFirstHit(c, g, d, h);
        ASSERT_TRUE(brute);
        const bool first = std::hypot(brute->point.x - p.point.x, brute->point.y - p.point.y) < 1e-6;
        EXPECT_EQ(g.isReached(p.arm, p.point, d), first) << "arm " << p.arm << " angle " << angle;
        (first ? reached : blocked) += 1;
      }
    }
    // Both answers occur (one arm alone is only masked by its neighbours).
    EXPECT_GT(reached, 50);
    EXPECT_GT(blocked, 5);
  }
}

TEST(ArmedCrossSection, CoverageIsTheShareOfAPeriodWhoseLinesFirstMeetACoatedSide) {
  PCG32 rng(13);
  for (const ArmsCase& c : kCases) {
    const ArmedCrossSection g = makeGeometry(c);
    for (int i = 0; i < 6; ++i) {
      const Vec2d d = unitAt((rng.nextDouble() - 0.5) * 2.8 + (i % 2 ? kPiDouble : 0.0));
      // The midpoint rule's error is at most the pieces' count over the lines.
      constexpr int kLines = 4000;
      EXPECT_NEAR(g.coverage(d), coatedShare(g, d, kLines), 40.0 / kLines);
    }
  }
}

TEST(ArmedCrossSection, OneArmIsTheEllipseBarbuleWithItsUpperHalfCoated) {
  // An ellipse, where BarbuleCrossSection's arc ends (normals +-pi/2 in float) fix their points;
  // on a superellipse's flat ends they do not, and the arc's ends move along them.
  const ArmsCase& c = kCases[4];
  const ArmedCrossSection arms = makeGeometry(c);
  const BarbuleCrossSection single(float(c.b), -kHalfPi, kHalfPi, float(radians(c.muDeg)), float(c.H), float(c.p));
  EXPECT_NEAR(arms.contactSpacing(),
              BarbuleCrossSection::contactSpacing(float(c.b), float(radians(c.muDeg)), float(c.p)), 1e-5);
  EXPECT_NEAR(arms.spacing(), single.spacing(), 1e-5);
  for (int i = 0; i <= 40; ++i) {
    const double angle = -1.5 + 3.0 * i / 40.0;
    const Vec2d d = unitAt(angle);
    const Vec2 toward(float(d.x), float(d.y));
    EXPECT_NEAR(arms.coverage(d), single.coverage(single.litArc(toward), toward), 2e-5) << angle;
  }
}

TEST(ArmedCrossSection, NeighboursAtTheContactSpacingTouchWithoutOverlapping) {
  for (const ArmsCase& c : kCases) {
    const ArmedCrossSection g = makeGeometry(c);
    // Every arm of the barbule against every arm of its neighbour: a point of one inside the other
    // would be an overlap, and just below the contact spacing there is one.
    auto deepestOverlap = [&](double H) {
      double deepest = 2.0;
      for (int a = 0; a < g.armCount(); ++a)
        for (int b = 0; b < g.armCount(); ++b)
          for (int i = 0; i < 2000; ++i) {
            const Vec2d dir = unitAt(2.0 * kPiDouble * i / 2000.0);
            const double r = std::pow(implicit(c, dir), -1.0 / c.p);
            const double angle = radians(c.tiltsDeg[size_t(a)] + c.muDeg);
            const Vec2d x{g.armCentre(a).x + r * (dir.x * std::cos(angle) - dir.y * std::sin(angle)),
                          g.armCentre(a).y + r * (dir.x * std::sin(angle) + dir.y * std::cos(angle))};
            const Vec2d centre{g.armCentre(b).x, g.armCentre(b).y + H};
            deepest = std::min(deepest, implicit(c, toArm(c, b, {x.x - centre.x, x.y - centre.y})));
          }
      return deepest;
    };
    EXPECT_GT(deepestOverlap(g.contactSpacing() * (1.0 + 1e-4)), 1.0 - 1e-3);
    EXPECT_LT(deepestOverlap(g.contactSpacing() * (1.0 - 1e-2)), 1.0);
    EXPECT_GE(g.spacing(), c.H);
  }
}

TEST(ArmedCrossSection, RefusesShapesItCannotBuild) {
  EXPECT_THROW(ArmedCrossSection({}, 0.2, 8.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ArmedCrossSection(std::vector<double>(kMaxBarbuleArms + 1, 0.0), 0.2, 8.0, 0.0, 1.0),
               std::invalid_argument);
  EXPECT_THROW(ArmedCrossSection({0.0, kHalfPi}, 0.2, 8.0, 0.0, 1.0), std::invalid_argument);
  // Arms folded back onto each other (their outlines coincide to rounding), semi-axes whose
  // points rounding decides, and a spacing or tilt that is not a number.
  EXPECT_THROW(ArmedCrossSection({radians(89.5), radians(-89.5)}, 0.25, 16.0, 0.0, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(ArmedCrossSection({radians(89.0), radians(-89.0)}, 0.25, 16.0, 0.0, 0.0));
  EXPECT_THROW(ArmedCrossSection({0.0}, 1e-5, 4.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ArmedCrossSection({0.0}, 200.0, 4.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(ArmedCrossSection({0.0}, 0.2, 4.0, 0.0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(ArmedCrossSection({0.0}, 0.2, 4.0, std::nan(""), 1.0), std::invalid_argument);
}

TEST(ArmedCrossSection, AHairpinAtTheLargestTiltsIsStillFollowedExactly) {
  // Two arms at +-89 degrees, joined end to end, lie almost on top of each other: coverage still
  // agrees with the lines followed one by one, and stays cheap (a handful of crossings).
  const ArmsCase c{{89.0, -89.0}, 0.25, 16.0, 0.0, 0.0};
  const ArmedCrossSection g = makeGeometry(c);
  for (double angle : {-0.972, -0.4, 0.3, 1.1}) {
    constexpr int kLines = 20000;
    EXPECT_NEAR(g.coverage(unitAt(angle)), coatedShare(g, unitAt(angle), kLines), 20.0 / kLines) << angle;
  }
}
TEST(ArmedCrossSection, CoverageAgreesWithTheLinesForRandomChains) {
  // Chains of 1 to 5 arms with random tilts, thickness, exponent, tilt and spacing: where one arm's
  // shadow alone holds a line, coverage decides from offsets, elsewhere from entry points; either
  // way it is the share of lines whose first hit is coated.
  PCG32 rng(77);
  for (int c = 0; c < 16; ++c) {
    std::vector<double> tilts(size_t(1 + int(rng.nextDouble() * 5)));
    for (double& t : tilts) t = radians((rng.nextDouble() - 0.5) * 170.0);
    const double b = 0.05 + rng.nextDouble() * 0.6, p = 2.0 + rng.nextDouble() * 14.0,
                 mu = (rng.nextDouble() - 0.5) * 2.0, H = rng.nextDouble() < 0.5 ? 0.0 : 1.0 + rng.nextDouble() * 8.0;
    const ArmedCrossSection g(tilts, b, p, mu, H);
    for (int j = 0; j < 2; ++j) {
      const Vec2d d = unitAt((rng.nextDouble() - 0.5) * 3.0 + (j % 2 ? kPiDouble : 0.0));
      constexpr int kLines = 20000;
      EXPECT_NEAR(g.coverage(d), coatedShare(g, d, kLines), 40.0 / kLines) << "chain " << c << ", direction " << j;
    }
  }
}
