// MirrorVisibleAngles against brute force: the longitudinal angles whose mirror direction leaves the
// point lit, found by testing each of a fine grid of angles with BarbuleCrossSection::isLit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>
#include "barbule/mirror_visibility.h"
#include "core/rng.h"

using namespace columba;

namespace {

struct Case {
  float b, H, mu, phi0, phi1;
  float p = 2.0f;  // superellipse exponent
};
// The reference scenes' barbules, a rounder tilted one, one packed at its contact spacing, and a
// thin one with a wide arc; then superellipses (the tangent-cone path): the reference shape at
// p 4, the packed one at p 8 and the thin one at p 16.
const Case kCases[] = {{0.25f, 1.25f, -0.35f, -0.37f, 2.64f},
                       {0.5f, 2.5f, 0.3f, -1.2f, 1.0f},
                       {0.35f, 1.0f, 0.6f, -0.5f, 2.0f},
                       {0.2f, 1.6f, -0.8f, 0.5f, 3.5f},
                       {0.25f, 1.25f, -0.35f, -0.37f, 2.64f, 4.0f},
                       {0.35f, 1.0f, 0.6f, -0.5f, 2.0f, 8.0f},
                       {0.2f, 1.6f, -0.8f, 0.5f, 3.5f, 16.0f}};

// omega_i's mirror direction about the normal with world in-plane normal n and angle theta.
Vec3 mirror(const Vec3& wi, Vec2 worldNormal, double theta) {
  Vec3 m = barbuleNormal(worldNormal, float(std::cos(theta)), float(std::sin(theta)));
  return m * (2.0f * dot(wi, m)) - wi;
}

struct BruteForce {
  double fraction;            // of theta's density on the lit angles
  std::vector<double> cdf;    // of the density restricted to them, at the grid's cell ends
  double thetaMin, thetaMax;  // the grid's range
};

// theta's density (proportional to omega_i . m) on `cells` cells, each tested at its middle.
BruteForce bruteForce(const BarbuleCrossSection& geometry, Vec2 localNormal, const Vec3& wi, int cells) {
  Vec2 n = geometry.toWorld(localNormal);
  LongitudinalDensity density(inPlaneProjection(wi, n), wi.y);
  BruteForce out{0.0, {0.0}, density.thetaMin(), density.thetaMax()};
  double total = 0.0, lit = 0.0;
  const double step = (out.thetaMax - out.thetaMin) / cells;
  for (int j = 0; j < cells; ++j) {
    double theta = out.thetaMin + (j + 0.5) * step;
    double weight = density.pdf(float(theta)) * step;
    total += weight;
    Vec3 wo = mirror(wi, n, theta);
    if (geometry.isLit(geometry.litArc(inPlane(wo).dir), localNormal)) lit += weight;
    out.cdf.push_back(lit);
  }
  out.fraction = total > 0.0 ? lit / total : 0.0;
  for (double& c : out.cdf) c = lit > 0.0 ? c / lit : 0.0;
  return out;
}

// A random omega_i above the vane and a point of its lit arc, uniform in offset; none where the
// arc is not lit from omega_i.
struct LitPoint {
  Vec3 wi;
  Vec2 localNormal;
};
std::optional<LitPoint> randomLitPoint(const BarbuleCrossSection& geometry, PCG32& rng) {
  float cosTheta = 0.05f + 0.95f * rng.nextFloat(), phi = kTwoPi * rng.nextFloat();
  float sinTheta = std::sqrt(1.0f - cosTheta * cosTheta);
  Vec3 wi(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
  LitArc arc = geometry.litArc(inPlane(wi).dir);
  if (!(arc.width() > 0.0f)) return std::nullopt;
  return LitPoint{wi, geometry.normalAt(geometry.pointAt(arc, arc.hMin + rng.nextFloat() * arc.width()))};
}

}  // namespace

TEST(MirrorVisibleAngles, VisibleShareMatchesTestingEveryAngle) {
  // 7 cross-sections x 400 (omega_i, offset) pairs; the share of theta's density at lit angles
  // against 4,000 angles tested one by one.
  PCG32 rng(11);
  int partial = 0, masked = 0, clear = 0;
  for (const Case& c : kCases) {
    BarbuleCrossSection geometry(c.b, c.phi0, c.phi1, c.mu, c.H, c.p);
    int partialHere = 0;
    for (int k = 0; k < 400; ++k) {
      std::optional<LitPoint> point = randomLitPoint(geometry, rng);
      if (!point) continue;
      const Vec3& wi = point->wi;
      const Vec2& localNormal = point->localNormal;
      MirrorVisibleAngles angles(geometry, localNormal, wi);
      BruteForce reference = bruteForce(geometry, localNormal, wi, 4000);
      EXPECT_NEAR(angles.visibleFraction(), reference.fraction, 2e-3)
          << "b " << c.b << " p " << c.p << " wi (" << wi.x << ", " << wi.y << ", " << wi.z << ")";
      if (reference.fraction == 0.0)
        ++masked;
      else if (reference.fraction == 1.0)
        ++clear;
      else
        ++partial, ++partialHere;
    }
    // Each cross-section, superellipses included, has points where the cuts matter.
    std::printf("b %g p %g: %d points partly masked\n", c.b, c.p, partialHere);
    EXPECT_GE(partialHere, 10) << "b " << c.b << " p " << c.p;
  }
  std::printf("%d points partly masked, %d wholly, %d not at all\n", partial, masked, clear);
  // Every kind of point was met, the partly masked ones (where the angles are cut) often enough.
  EXPECT_GT(partial, 20);
  EXPECT_GT(masked, 20);
  EXPECT_GT(clear, 100);
}

TEST(MirrorVisibleAngles, SamplesAreLitAndFollowTheRestrictedDensity) {
  // At partly masked points, 1,000 stratified samples: all but a few lit (float rounding where a
  // cut is ill-conditioned, near the largest a), and their distribution the restricted density's
  // (the count below each of 20 quantiles of the brute-force CDF within 1 % of the samples). Points
  // with less than 10 % visible are left out: there one cell of the brute-force grid holds more
  // than 1 % of the visible mass.
  PCG32 rng(5);
  int checked = 0;
  for (const Case& c : kCases) {
    BarbuleCrossSection geometry(c.b, c.phi0, c.phi1, c.mu, c.H, c.p);
    int checkedHere = 0;
    for (int k = 0; k < 4000 && checkedHere < 40; ++k) {
      std::optional<LitPoint> point = randomLitPoint(geometry, rng);
      if (!point) continue;
      const Vec3& wi = point->wi;
      const Vec2& localNormal = point->localNormal;
      MirrorVisibleAngles angles(geometry, localNormal, wi);
      if (!(angles.visibleFraction() > 0.1f && angles.visibleFraction() < 0.99f)) continue;
      ++checked;
      ++checkedHere;
      const int cells = 4000, samples = 1000;
      BruteForce reference = bruteForce(geometry, localNormal, wi, cells);
      std::vector<double> thetas;
      int unlit = 0;
      for (int s = 0; s < samples; ++s) {
        float theta = angles.sample((s + 0.5f) / samples).theta;
        thetas.push_back(theta);
        Vec3 wo = mirror(wi, angles.worldNormal(), theta);
        unlit += !geometry.isLit(geometry.litArc(inPlane(wo).dir), localNormal);
      }
      EXPECT_LE(unlit, 2) << "samples outside the lit angles";
      const double step = (reference.thetaMax - reference.thetaMin) / cells;
      for (int q = 1; q < 20; ++q) {
        // The grid angle where the brute-force CDF reaches q / 20, and the samples below it.
        int cell = 0;
        while (cell < cells && reference.cdf[size_t(cell) + 1] < q / 20.0) ++cell;
        double theta = reference.thetaMin + (cell + 1) * step;
        int below = 0;
        for (double t : thetas) below += t <= theta;
        EXPECT_NEAR(below, q * samples / 20, 0.01 * samples + 2) << "quantile " << q << " of case b " << c.b;
      }
    }
    EXPECT_GE(checkedHere, 5) << "b " << c.b << " p " << c.p;
  }
  EXPECT_GE(checked, 100);
}
