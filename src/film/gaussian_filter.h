#pragma once
// The Gaussian filter (Mitsuba 3's `gaussian`): a separable normal distribution of standard
// deviation `stddev` pixels truncated at radius 4 stddev, sampled exactly by inverting its CDF
// with a closed-form inverse error function (no tables to miss in the cache per camera sample).
#include <memory>
#include "film/reconstruction_filter.h"

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
  float cdfLimit_;            // erf(radius / (stddev sqrt 2))
  double evalAxis(double x) const;
  float sampleAxis(float u) const;
};

// <rfilter type="gaussian">: stddev (0.5).
std::shared_ptr<Object> makeGaussianFilter(const Properties& props);

}  // namespace columba
