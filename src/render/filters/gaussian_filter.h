#pragma once
// The Gaussian filter (Mitsuba 3's `gaussian`): a separable normal distribution of standard
// deviation `stddev` pixels truncated at radius 4 stddev. It is sampled by inverting its CDF
// tabulated at construction on a fine grid of offsets (piecewise-constant density within
// 1/1000 pixel cells): solving erf per camera sample was a measurable part of a render's time.
#include <array>
#include <cstdint>
#include <memory>
#include "render/reconstruction_filter.h"

namespace columba {

class Properties;

class GaussianFilter : public ReconstructionFilter {
 public:
  explicit GaussianFilter(float stddev = 0.5f);
  float radius() const override { return radius_; }
  // The normalised filter, i.e. the density of sample().
  float eval(Vec2 offset) const override;
  Vec2 sample(Vec2 u) const override;

 private:
  float stddev_, radius_;
  double axisNormalization_;  // 1 / the integral of the truncated 1D Gaussian
  double cdfLimit_;           // erf(radius / (stddev sqrt 2))
  static constexpr int kCdfSize = 4097;
  std::array<float, kCdfSize> cdf_;  // at offsets -radius + 2 radius i / (size - 1)
  // guide_[j]: the last CDF entry at or below j / kGuideSize, where the search for u starts.
  // Neighbouring CDF entries differ by at least 7.8e-4 (8 / (4096 sqrt(2 pi)) at the centre,
  // whatever the stddev), more than a guide cell, so the search takes at most one step.
  static constexpr int kGuideSize = 4096;
  std::array<uint16_t, kGuideSize> guide_;
  double evalAxis(double x) const;
  float sampleAxis(float u) const;
};

// <rfilter type="gaussian">: stddev (0.5).
std::shared_ptr<Object> makeGaussianFilter(const Properties& props);

}  // namespace columba
