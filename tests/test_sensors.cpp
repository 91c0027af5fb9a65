// The BSDF visualiser's image disk: rays inside it, none outside, and the footprint test the
// renderer skips pixels with.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include "core/rng.h"
#include "render/film.h"
#include "render/filters/gaussian_filter.h"
#include "render/samplers/independent_sampler.h"
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
