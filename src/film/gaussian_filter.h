#pragma once
// The Gaussian filter (Mitsuba 3's `gaussian`): on each axis a windowed Gaussian of standard
// deviation `stddev` pixels, exp(-x^2 / (2 stddev^2)) less its value at the radius, 4 stddev, so
// that it falls to zero there without a step; normalised.
#include <memory>
#include "film/reconstruction_filter.h"

namespace columba {

class Properties;

class GaussianFilter : public ReconstructionFilter {
 public:
  explicit GaussianFilter(float stddev = 0.5f);
  float radius() const override { return radius_; }
  float eval(float offset) const override;

 private:
  float stddev_, radius_;
  float atRadius_;       // exp(-radius^2 / (2 stddev^2))
  float normalization_;  // 1 / the integral of the windowed Gaussian
};

// <rfilter type="gaussian">: its parameters are in docs/reference/rfilters.md.
std::shared_ptr<Object> makeGaussianFilter(const Properties& props);

}  // namespace columba
