#include "render/filters/gaussian_filter.h"

#include <cmath>
#include "scene/properties.h"

namespace columba {

namespace {
// The inverse error function for |y| < 1: Winitzki's closed-form approximation (relative error
// below 2e-3), polished by Newton steps on erf, which converge quadratically from there.
double inverseErf(double y) {
  const double a = 0.147, pi = 3.14159265358979323846;
  double l = std::log((1.0 - y) * (1.0 + y));
  double t = 2.0 / (pi * a) + 0.5 * l;
  double x = std::copysign(std::sqrt(std::sqrt(t * t - l / a) - t), y);
  for (int i = 0; i < 3; ++i) x -= (std::erf(x) - y) / (2.0 / std::sqrt(pi) * std::exp(-x * x));
  return x;
}
}  // namespace

GaussianFilter::GaussianFilter(float stddev) : stddev_(stddev), radius_(4.0f * stddev) {
  cdfLimit_ = std::erf(radius_ / (stddev_ * std::sqrt(2.0)));
  axisNormalization_ = 1.0 / (stddev_ * std::sqrt(2.0 * 3.14159265358979323846) * cdfLimit_);
}

double GaussianFilter::evalAxis(double x) const {
  if (std::abs(x) > radius_) return 0.0;
  return axisNormalization_ * std::exp(-x * x / (2.0 * double(stddev_) * stddev_));
}

float GaussianFilter::eval(Vec2 offset) const { return float(evalAxis(offset.x) * evalAxis(offset.y)); }

// Inverts the truncated normal's CDF, erf(x / (stddev sqrt 2)) mapped from [-limit, limit].
float GaussianFilter::sampleAxis(float u) const {
  double y = (2.0 * u - 1.0) * cdfLimit_;
  float x = float(stddev_ * std::sqrt(2.0) * inverseErf(y));
  return std::fmin(std::fmax(x, -radius_), radius_);
}

Vec2 GaussianFilter::sample(Vec2 u) const { return {sampleAxis(u.x), sampleAxis(u.y)}; }

std::shared_ptr<Object> makeGaussianFilter(const Properties& props) {
  float stddev = props.getFloat("stddev", 0.5f);
  if (!(stddev > 0.0f) || !std::isfinite(stddev)) throw props.error("stddev", "must be a positive number");
  return std::make_shared<GaussianFilter>(stddev);
}

}  // namespace columba
