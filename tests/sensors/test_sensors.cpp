// The BSDF visualiser's image disk: rays inside it, none outside, and the footprint test the
// renderer skips pixels with.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include "core/rng.h"
#include "film/film.h"
#include "film/gaussian_filter.h"
#include "samplers/independent_sampler.h"
#include "sensors/bsdf_visualizer_sensor.h"

using namespace columba;

namespace {
BSDFVisualizerSensor visualizer(int width, int height) {
  return BSDFVisualizerSensor(std::make_shared<Film>(width, height, std::make_shared<GaussianFilter>()),
                              std::make_shared<IndependentSampler>(1, 0), 0.1f);
}
}  // namespace

TEST(BSDFVisualizerSensor, RaysLookAtTheOriginFromTheHemisphere) {
  BSDFVisualizerSensor sensor = visualizer(64, 64);
  // The image centre looks straight down; the disk's rim is the horizon.
  std::optional<Ray> centre = sensor.generateRay(Vec2(32.0f, 32.0f));
  ASSERT_TRUE(centre.has_value());
  EXPECT_NEAR(centre->d.z, -1.0f, 1e-6f);
  std::optional<Ray> rim = sensor.generateRay(Vec2(63.99f, 32.0f));
  ASSERT_TRUE(rim.has_value());
  EXPECT_NEAR(rim->d.z, 0.0f, 1e-3f);
  EXPECT_FALSE(sensor.generateRay(Vec2(0.5f, 0.5f)).has_value());
}

TEST(BSDFVisualizerSensor, ImageRowsGrowTowardPlusY) {
  // The paper's mapping: v = 2 p_y / H - 1 grows downward with the row, so a film point in the
  // upper half of the image looks from the -y side of the hemisphere.
  BSDFVisualizerSensor sensor = visualizer(64, 64);
  std::optional<Ray> upper = sensor.generateRay(Vec2(32.0f, 16.0f));
  ASSERT_TRUE(upper.has_value());
  EXPECT_LT(upper->o.y, 0.0f);
  EXPECT_NEAR(upper->o.x, 0.0f, 1e-6f);
  std::optional<Ray> lower = sensor.generateRay(Vec2(32.0f, 48.0f));
  ASSERT_TRUE(lower.has_value());
  EXPECT_GT(lower->o.y, 0.0f);
}

TEST(BSDFVisualizerSensor, MirrorDirectionLandsWhereTheMappingSays) {
  // A light at polar angle theta and azimuth phi has its mirror direction at (theta, phi + pi):
  // r = theta / (pi/2), (u, v) = r (cos(phi + pi), sin(phi + pi)), pixel ((u + 1) W/2, (v + 1) H/2).
  const int W = 200, H = 100;
  BSDFVisualizerSensor sensor = visualizer(W, H);
  for (float thetaDeg : {10.0f, 30.0f, 55.0f, 80.0f})
    for (float phiDeg : {0.0f, 40.0f, 90.0f, 200.0f, 300.0f}) {
      float theta = degToRad(thetaDeg), phi = degToRad(phiDeg);
      Vec3 light(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      Vec3 mirror(-light.x, -light.y, light.z);
      float r = theta / kHalfPi;
      Vec2 pixel((r * std::cos(phi + kPi) + 1.0f) * W / 2, (r * std::sin(phi + kPi) + 1.0f) * H / 2);
      std::optional<Ray> ray = sensor.generateRay(pixel);
      ASSERT_TRUE(ray.has_value());
      // The ray starts at the mirror direction and looks at the origin.
      Vec3 from = normalize(ray->o);
      EXPECT_NEAR(dot(from, mirror), 1.0f, 1e-5f) << thetaDeg << " " << phiDeg;
      EXPECT_NEAR(dot(ray->d, -mirror), 1.0f, 1e-5f);
    }
}

TEST(BSDFVisualizerSensor, FootprintsWithoutRaysAreReportedEmpty) {
  BSDFVisualizerSensor sensor = visualizer(40, 30);
  PCG32 rng(3);
  int empty = 0, seen = 0;
  for (int i = 0; i < 4000; ++i) {
    Vec2 lo(rng.nextFloat() * 44.0f - 2.0f, rng.nextFloat() * 34.0f - 2.0f);
    Vec2 hi = lo + Vec2(rng.nextFloat() * 5.0f, rng.nextFloat() * 5.0f);
    bool anyRay = false;
    for (int j = 0; j < 400 && !anyRay; ++j) {
      Vec2 p(lo.x + rng.nextFloat() * (hi.x - lo.x), lo.y + rng.nextFloat() * (hi.y - lo.y));
      anyRay = sensor.generateRay(p).has_value();
    }
    // A ray found inside proves the rectangle is seen; an empty verdict must hold for every point.
    if (anyRay) {
      EXPECT_TRUE(sensor.seesAnyOf(lo, hi));
    }
    if (sensor.seesAnyOf(lo, hi)) {
      ++seen;
    } else {
      ++empty;
    }
  }
  EXPECT_GT(empty, 400);
  EXPECT_GT(seen, 400);
}
