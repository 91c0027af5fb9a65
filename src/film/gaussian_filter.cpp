#include "film/gaussian_filter.h"

#include <cmath>
#include "core/fast_math.h"
#include "core/properties.h"

namespace columba {

GaussianFilter::GaussianFilter(float stddev) : stddev_(stddev), radius_(4.0f * stddev) {
  cdfLimit_ = std::erf(radius_ / (stddev_ * std::sqrt(2.0)));
  axisNormalization_ = 1.0 / (stddev_ * std::sqrt(2.0 * kPiDouble) * cdfLimit_);
}

double GaussianFilter::evalAxis(double x) const {
  if (std::abs(x) > radius_) return 0.0;
  return axisNormalization_ * std::exp(-x * x / (2.0 * double(stddev_) * stddev_));
}

float GaussianFilter::eval(Vec2 offset) const { return float(evalAxis(offset.x) * evalAxis(offset.y)); }

// Inverts the truncated normal's CDF, erf(x / (stddev sqrt 2)) mapped from [-limit, limit].
float GaussianFilter::sampleAxis(float u) const {
  float offset = std::sqrt(2.0f) * stddev_ * erfInverse((2.0f * u - 1.0f) * cdfLimit_);
  return clampf(offset, -radius_, radius_);
}

Vec2 GaussianFilter::sample(Vec2 u) const { return {sampleAxis(u.x), sampleAxis(u.y)}; }

std::shared_ptr<Object> makeGaussianFilter(const Properties& props) {
  float stddev = props.getFloat("stddev", 0.5f);
  if (!(stddev > 0.0f) || !std::isfinite(stddev)) throw props.error("stddev", "must be a positive number");
  return std::make_shared<GaussianFilter>(stddev);
}

}  // namespace columba
