#include "render/filters/gaussian_filter.h"

#include <algorithm>
#include <cmath>
#include "core/math.h"
#include "scene/properties.h"

namespace columba {

GaussianFilter::GaussianFilter(float stddev) : stddev_(stddev), radius_(4.0f * stddev) {
  cdfLimit_ = std::erf(radius_ / (stddev_ * std::sqrt(2.0)));
  axisNormalization_ = 1.0 / (stddev_ * std::sqrt(2.0 * 3.14159265358979323846) * cdfLimit_);
  const double scale = 1.0 / (stddev_ * std::sqrt(2.0));
  for (int i = 0; i < kCdfSize; ++i) {
    double x = -radius_ + 2.0 * radius_ * i / (kCdfSize - 1);
    cdf_[i] = float(0.5 * (1.0 + std::erf(x * scale) / cdfLimit_));
  }
  cdf_.front() = 0.0f;
  cdf_.back() = 1.0f;
  for (int j = 0, i = 0; j < kGuideSize; ++j) {
    while (i + 1 < kCdfSize - 1 && cdf_[i + 1] <= float(j) / kGuideSize) ++i;
    guide_[j] = uint16_t(i);
  }
}

double GaussianFilter::evalAxis(double x) const {
  if (std::abs(x) > radius_) return 0.0;
  return axisNormalization_ * std::exp(-x * x / (2.0 * double(stddev_) * stddev_));
}

float GaussianFilter::eval(Vec2 offset) const { return float(evalAxis(offset.x) * evalAxis(offset.y)); }

// Inverts the truncated normal's CDF, erf(x / (stddev sqrt 2)) mapped from [-limit, limit].
float GaussianFilter::sampleAxis(float u) const {
  u = clampf(u, 0.0f, 1.0f);
  int i = guide_[std::min(int(u * kGuideSize), kGuideSize - 1)];
  while (i + 1 < kCdfSize - 1 && cdf_[i + 1] <= u) ++i;
  float width = cdf_[i + 1] - cdf_[i];
  float t = width > 0.0f ? clampf((u - cdf_[i]) / width, 0.0f, 1.0f) : 0.5f;
  return -radius_ + 2.0f * radius_ * (float(i) + t) / float(kCdfSize - 1);
}

Vec2 GaussianFilter::sample(Vec2 u) const { return {sampleAxis(u.x), sampleAxis(u.y)}; }

std::shared_ptr<Object> makeGaussianFilter(const Properties& props) {
  float stddev = props.getFloat("stddev", 0.5f);
  if (!(stddev > 0.0f) || !std::isfinite(stddev)) throw props.error("stddev", "must be a positive number");
  return std::make_shared<GaussianFilter>(stddev);
}

}  // namespace columba
