// Where Columba's barbule model deliberately differs from the paper's own implementation, stated
// as numbers computed from Columba's BSDF, so that the remaining brightness differences between
// the two renderers' images of the reference scenes are accounted for:
// - simulation1 and simulation2: the reference's evaluation divides D by H twice, so its R lobe is
//   Columba's divided by H (H = 1.25);
// - simulation3: the reference's neighbours mask with their reflective arc only, Columba's with the
//   whole ellipse, so at some grazing directions across the barbules Columba's coverage is smaller.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include "barbule/cross_section.h"
#include "bsdfs/barbulebsdf.h"
#include "core/illuminant.h"
#include "core/spectrum.h"
#include "core/transform.h"

using namespace columba;

namespace {
BarbuleParameters referenceParameters(float height) {
  BarbuleParameters p;  // b 0.25, phi (-0.37, 2.64), mu -0.35, H 1.25
  p.height = height;
  return p;
}

// Luminance of the simulation's visualiser image (pixels on the disk, as the `bsdfvisualizer`
// maps them) for a light from `lightWorld`, with the R lobe scaled by `rScale`: the image of
// `barbulebsdfev`, f(light, camera) |cos camera|, in the frame of a rectangle turned by `toWorld`.
double imageLuminance(const BarbuleBSDF& bsdf, const Transform& toWorld, Vec3 lightWorld, float rScale) {
  const Transform toLocal = toWorld.inverse();
  const Vec3 light = normalize(toLocal.vector(normalize(lightWorld)));
  const int res = 48;
  double sum = 0.0;
  for (int py = 0; py < res; ++py)
    for (int px = 0; px < res; ++px) {
      float u = 2.0f * (px + 0.5f) / res - 1.0f, v = 2.0f * (py + 0.5f) / res - 1.0f;
      float r = std::sqrt(u * u + v * v);
      if (r >= 1.0f) continue;
      float theta = r * kHalfPi, phi = std::atan2(v, u);
      Vec3 cameraWorld(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      Vec3 camera = normalize(toLocal.vector(cameraWorld));
      for (float l = 380.0f; l < 780.0f; l += 4 * 5.0f) {
        Wavelengths wl = Wavelengths::fixed({l, l + 5.0f, l + 10.0f, l + 15.0f});
        BarbuleBSDF::Lobes f = bsdf.evalLobes(BSDFContext{}, light, camera, wl);
        for (int k = 0; k < kSpectrumSamples; ++k)
          sum += double(rScale * f.reflection[k] + f.trt[k]) * std::abs(camera.z) * cieXYZ(wl[k]).y * d65(wl[k]);
      }
    }
  return sum;
}
}  // namespace

TEST(ReferenceDifferences, ReferenceDividesTheRLobeByHOnceMore) {
  // simulation1: rectangle turned by rotate z -52 after rotate x -15; the disk light's centre at
  // (0.3, -0.3, 1). simulation2: rotate y 5; light at (0, 0, 1).
  struct Case {
    const char* name;
    float height;
    Transform toWorld;
    Vec3 light;
    double measured;  // brightness ratio Columba / reference seen on the two renderers' images
  };
  const Case cases[] = {
      {"simulation1", 0.58f, Transform::rotate(Vec3(0, 0, 1), -52) * Transform::rotate(Vec3(1, 0, 0), -15),
       Vec3(0.3f, -0.3f, 1.0f), 1.14},
      {"simulation2", 0.58f, Transform::rotate(Vec3(0, 1, 0), 5), Vec3(0, 0, 1), 1.15},
  };
  for (const Case& c : cases) {
    BarbuleParameters p = referenceParameters(c.height);
    BarbuleBSDF bsdf(p, BarbuleBSDF::Role::LightIncident);
    double columba = imageLuminance(bsdf, c.toWorld, c.light, 1.0f);
    double reference = imageLuminance(bsdf, c.toWorld, c.light, 1.0f / p.H);
    double ratio = columba / reference;
    std::printf(
        "%s: image luminance with Columba's R lobe / with R divided by H = %.2f once more: %.3f "
        "(seen between the renderers: %.2f)\n",
        c.name, p.H, ratio, c.measured);
    // The defect alone accounts for the measured ratio to within 0.05.
    EXPECT_NEAR(ratio, c.measured, 0.05) << c.name;
    EXPECT_GT(ratio, 1.0);
    EXPECT_LT(ratio, double(p.H));
  }
}

namespace {
// Fraction of the projected period that the central barbule's reflective arc covers for light
// along the world 2D direction `toward`, by dense 2D ray casting against the central ellipse and
// its neighbours at +-H. With `neighboursWhole` the neighbours block with the whole ellipse
// (Columba); otherwise a ray passes through a neighbour's uncoated part (the reference).
double castCoverage(const BarbuleCrossSection& g, Vec2 toward, bool neighboursWhole) {
  const float H = g.spacing();
  Vec2 across(-toward.y, toward.x);
  const int n = 20000;
  const float extent = 3.0f;  // offsets across the direction; wider than three barbules
  int lit = 0;
  for (int i = 0; i < n; ++i) {
    float h = -extent + 2.0f * extent * (i + 0.5f) / n;
    Vec2 origin = across * h + toward * 10.0f, dir = toward * -1.0f;
    // The nearest hit among the three ellipses that counts as a blocker.
    float best = 1e30f;
    int who = -2;
    for (int k = -1; k <= 1; ++k) {
      Vec2 shifted = origin - Vec2(0.0f, k * H);  // ellipse k sits at (0, k H)
      std::optional<float> t = g.intersect(shifted, dir);
      if (!t || *t >= best) continue;
      // The reference asks only whether a neighbour's first crossing lies on its coated arc.
      if (k != 0 && !neighboursWhole && !g.onReflectiveArc(g.normalAt(g.toLocal(shifted + dir * *t)))) continue;
      best = *t;
      who = k;
    }
    if (who != 0) continue;
    Vec2 p = g.toLocal(origin + dir * best);
    if (g.onReflectiveArc(g.normalAt(p))) ++lit;
  }
  double width = 2.0 * extent * lit / n;
  return std::min(width / (H * std::abs(toward.x)), 1.0);
}
}  // namespace

TEST(ReferenceDifferences, ReferenceNeighboursMaskOnlyWithTheirCoatedArc) {
  BarbuleParameters p = referenceParameters(0.59f);
  BarbuleCrossSection g(p.b, p.phi0, p.phi1, p.mu, p.H);
  // Columba's own coverage agrees with the brute-force caster where neighbours are whole.
  for (float gammaDeg : {-60.0f, -20.0f, 0.0f, 30.0f, 70.0f}) {
    Vec2 toward(std::cos(degToRad(gammaDeg)), std::sin(degToRad(gammaDeg)));
    EXPECT_NEAR(castCoverage(g, toward, true), g.coverage(g.litArc(toward), toward), 2e-3) << gammaDeg;
  }
  // The reference's neighbours hide less: its coverage is never smaller. For the reference
  // scenes' barbules (H 1.25, close to contact) the incident coverage differs only where the
  // light grazes across the barbules from x+, around gamma = 45-50 degrees, by up to 0.8 %;
  // elsewhere the blocking part of a neighbour is its coated arc either way.
  double largestGain = 0.0, largestGainAt = 0.0;
  for (float gammaDeg = -85.0f; gammaDeg <= 85.0f; gammaDeg += 5.0f) {
    Vec2 toward(std::cos(degToRad(gammaDeg)), std::sin(degToRad(gammaDeg)));
    double whole = castCoverage(g, toward, true), arcOnly = castCoverage(g, toward, false);
    EXPECT_GE(arcOnly, whole - 1e-3) << gammaDeg;
    if (arcOnly - whole > largestGain) {
      largestGain = arcOnly - whole;
      largestGainAt = gammaDeg;
    }
  }
  std::printf("largest coverage gain of coated-arc-only masking: %.4f at gamma %.0f deg\n", largestGain, largestGainAt);
  EXPECT_GT(largestGain, 0.005);
  EXPECT_LT(largestGain, 0.02);
  EXPECT_GT(largestGainAt, 40.0);
  EXPECT_LT(largestGainAt, 55.0);
}
