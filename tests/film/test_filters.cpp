#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>
#include "core/math.h"
#include "core/properties.h"
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

// Midpoint-rule integral of eval over [x0, x1].
double integrate(const ReconstructionFilter& filter, double x0, double x1, int steps) {
  double sum = 0, dx = (x1 - x0) / steps;
  for (int i = 0; i < steps; ++i) sum += filter.eval(float(x0 + (i + 0.5) * dx));
  return sum * dx;
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
  EXPECT_NO_THROW(makeGaussianFilter(gaussianProperties(4.0f)));
  EXPECT_THROW(makeGaussianFilter(gaussianProperties(4.5f)), InputError);
  EXPECT_NO_THROW(makeGaussianFilter(gaussianProperties(0.125f)));
  for (float narrow : {0.1f, 1e-6f, 1e-40f}) EXPECT_THROW(makeGaussianFilter(gaussianProperties(narrow)), InputError);
}

TEST(FilterEval, IsANormalisedDensityWithinTheRadius) {
  for (const auto& filter : allFilters()) {
    float r = filter->radius();
    EXPECT_NEAR(integrate(*filter, -r, r, 20000), 1.0, 1e-5) << "radius " << r;
    EXPECT_EQ(filter->eval(1.01f * r), 0.0f);
    EXPECT_EQ(filter->eval(-1.01f * r), 0.0f);
    EXPECT_GT(filter->eval(0.0f), 0.0f);
  }
}

TEST(FilterEval, GaussianIsMitsubasWindowedGaussian) {
  // exp(-x^2 / (2 s^2)) - exp(-8), over its integral s sqrt(2 pi) erf(2 sqrt 2) - 8 s exp(-8).
  GaussianFilter filter(0.5f);
  const double s = 0.5, bias = std::exp(-8.0);
  const double mass = s * std::sqrt(2.0 * kPiDouble) * std::erf(2.0 * std::sqrt(2.0)) - 8.0 * s * bias;
  EXPECT_NEAR(filter.eval(0.0f), (1.0 - bias) / mass, 1e-6);
  EXPECT_NEAR(filter.eval(0.5f), (std::exp(-0.5) - bias) / mass, 1e-6);
  EXPECT_NEAR(filter.eval(-1.0f), (std::exp(-2.0) - bias) / mass, 1e-6);
  EXPECT_NEAR(filter.eval(1.999f), 0.0, 1e-5);
}

TEST(FilterFactories, TentTakesMitsubasRadius) {
  Properties tent;
  tent.type = "tent";
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeTentFilter(tent))->radius(), 1.0f);
  Properties wide = filterProperties("tent", "radius", 2.0f);
  EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<ReconstructionFilter>(makeTentFilter(wide))->radius(), 2.0f);
  EXPECT_NO_THROW(wide.checkAllUsed());
  EXPECT_NO_THROW(makeTentFilter(filterProperties("tent", "radius", 0.5f)));
  for (float bad : {0.0f, -1.0f, 0.4f, 17.0f})
    EXPECT_THROW(makeTentFilter(filterProperties("tent", "radius", bad)), InputError);
}

TEST(FilterEval, TentMatchesItsClosedForm) {
  // (1 - |x| / r) / r.
  TentFilter filter(2.0f);
  EXPECT_FLOAT_EQ(filter.eval(0.0f), 0.5f);
  EXPECT_FLOAT_EQ(filter.eval(1.0f), 0.25f);
  EXPECT_FLOAT_EQ(filter.eval(-1.5f), 0.125f);
  EXPECT_EQ(filter.eval(2.01f), 0.0f);
}
