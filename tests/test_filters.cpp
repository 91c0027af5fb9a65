#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>
#include "chi_square.h"
#include "core/properties.h"
#include "core/rng.h"
#include "film/box_filter.h"
#include "film/gaussian_filter.h"
#include "film/tent_filter.h"

using namespace columba;

namespace {

// An <rfilter> of `type` with the float parameter `name` set to `number`.
Properties filterProperties(const std::string& type, const std::string& name, float number) {
  Properties props;
  props.tag = "rfilter";
  props.type = type;
  Properties::Value value;
  value.kind = Properties::ValueKind::Float;
  value.number = number;
  props.set(name, value);
  return props;
}

Properties gaussianProperties(float stddev) { return filterProperties("gaussian", "stddev", stddev); }

std::vector<std::shared_ptr<ReconstructionFilter>> allFilters() {
  return {std::make_shared<BoxFilter>(), std::make_shared<GaussianFilter>(0.5f), std::make_shared<GaussianFilter>(1.2f),
          std::make_shared<TentFilter>(1.0f), std::make_shared<TentFilter>(2.5f)};
}

// Midpoint-rule integral of eval over [x0, x1] x [y0, y1].
double integrate(const ReconstructionFilter& filter, double x0, double x1, double y0, double y1, int steps) {
  double sum = 0, dx = (x1 - x0) / steps, dy = (y1 - y0) / steps;
  for (int i = 0; i < steps; ++i)
    for (int j = 0; j < steps; ++j) sum += filter.eval(Vec2(float(x0 + (i + 0.5) * dx), float(y0 + (j + 0.5) * dy)));
  return sum * dx * dy;
}

}  // namespace

TEST(FilterFactories, MitsubaParametersAndRadii) {
  Properties box;
  box.type = "box";
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeBoxFilter(box))->radius(), 0.5f);
  Properties gaussian;
  gaussian.type = "gaussian";
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeGaussianFilter(gaussian))->radius(), 2.0f);
  Properties wide = gaussianProperties(1.0f);
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeGaussianFilter(wide))->radius(), 4.0f);
  EXPECT_NO_THROW(wide.checkAllUsed());
  EXPECT_THROW(makeGaussianFilter(gaussianProperties(0.0f)), InputError);
  EXPECT_THROW(makeGaussianFilter(gaussianProperties(-1.0f)), InputError);
}

TEST(FilterEval, IsANormalisedDensityWithinTheRadius) {
  for (const auto& filter : allFilters()) {
    float r = filter->radius();
    EXPECT_NEAR(integrate(*filter, -r, r, -r, r, 400), 1.0, 1e-4) << "radius " << r;
    EXPECT_EQ(filter->eval(Vec2(1.01f * r, 0.0f)), 0.0f);
    EXPECT_EQ(filter->eval(Vec2(0.0f, -1.01f * r)), 0.0f);
    EXPECT_GT(filter->eval(Vec2(0.0f, 0.0f)), 0.0f);
  }
}

TEST(FilterSample, StaysWithinTheRadius) {
  const float almostOne = 0x1.fffffep-1f;
  for (const auto& filter : allFilters()) {
    float r = filter->radius();
    for (Vec2 u : {Vec2(0, 0), Vec2(almostOne, almostOne), Vec2(0, almostOne), Vec2(0.5f, 0.5f)}) {
      Vec2 p = filter->sample(u);
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y));
      EXPECT_LE(std::abs(p.x), r);
      EXPECT_LE(std::abs(p.y), r);
    }
    EXPECT_NEAR(filter->sample(Vec2(0.5f, 0.5f)).x, 0.0f, 1e-6f);
    PCG32 rng(3);
    for (int i = 0; i < 100000; ++i) {
      Vec2 p = filter->sample(Vec2(rng.nextFloat(), rng.nextFloat()));
      ASSERT_LE(std::abs(p.x), r);
      ASSERT_LE(std::abs(p.y), r);
    }
  }
}

TEST(FilterSample, DistributionMatchesEval) {
  const int bins = 24, sampleCount = 1000000;
  for (const auto& filter : allFilters()) {
    const double r = filter->radius(), width = 2.0 * r / bins;
    std::vector<double> observed(bins * bins, 0.0), expected(bins * bins, 0.0);
    PCG32 rng(17, 5);
    for (int i = 0; i < sampleCount; ++i) {
      Vec2 p = filter->sample(Vec2(rng.nextFloat(), rng.nextFloat()));
      int bx = std::clamp(int((p.x + r) / width), 0, bins - 1), by = std::clamp(int((p.y + r) / width), 0, bins - 1);
      observed[by * bins + bx] += 1.0;
    }
    for (int by = 0; by < bins; ++by)
      for (int bx = 0; bx < bins; ++bx)
        expected[by * bins + bx] = sampleCount * integrate(*filter, -r + bx * width, -r + (bx + 1) * width,
                                                           -r + by * width, -r + (by + 1) * width, 12);
    auto result = columba::testing::chiSquareTest(observed, expected);
    EXPECT_GT(result.pValue, 0.01) << "radius " << r << ": " << result.message;
  }
}

TEST(FilterSample, GaussianMatchesTheTruncatedNormalQuantiles) {
  // The fraction of offsets within one standard deviation on an axis.
  GaussianFilter filter(0.5f);
  const double expected = std::erf(1.0 / std::sqrt(2.0)) / std::erf(4.0 / std::sqrt(2.0));
  const int n = 100000;
  int inside = 0;
  for (int i = 0; i < n; ++i) inside += std::abs(filter.sample(Vec2((i + 0.5f) / n, 0.5f)).x) < 0.5f;
  EXPECT_NEAR(double(inside) / n, expected, 2.0 / n);
}

TEST(FilterFactories, TentTakesMitsubasRadius) {
  Properties tent;
  tent.type = "tent";
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeTentFilter(tent))->radius(), 1.0f);
  Properties wide = filterProperties("tent", "radius", 2.0f);
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeTentFilter(wide))->radius(), 2.0f);
  EXPECT_NO_THROW(wide.checkAllUsed());
  for (float bad : {0.0f, -1.0f}) EXPECT_THROW(makeTentFilter(filterProperties("tent", "radius", bad)), InputError);
}

TEST(FilterSample, TentMatchesItsClosedForm) {
  // Per axis the density is (1 - |x|/r) / r; an eighth of it lies below -r/2 and above r/2.
  TentFilter filter(2.0f);
  EXPECT_FLOAT_EQ(filter.eval(Vec2(0, 0)), 0.25f);
  EXPECT_FLOAT_EQ(filter.eval(Vec2(1, 0)), 0.125f);
  EXPECT_FLOAT_EQ(filter.eval(Vec2(1, -1)), 0.0625f);
  EXPECT_EQ(filter.eval(Vec2(2.01f, 0)), 0.0f);
  EXPECT_NEAR(filter.sample(Vec2(0.125f, 0.875f)).x, -1.0f, 1e-6f);
  EXPECT_NEAR(filter.sample(Vec2(0.125f, 0.875f)).y, 1.0f, 1e-6f);
  EXPECT_NEAR(filter.sample(Vec2(0.5f, 0.0f)).y, -2.0f, 1e-6f);
}
