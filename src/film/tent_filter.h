#pragma once
// The tent filter (Mitsuba's `tent`): on each axis a triangle falling linearly from the pixel's
// centre to zero at `radius` pixels (1 by default), sampled exactly by inverting its CDF.
#include <memory>
#include "film/reconstruction_filter.h"

namespace columba {

class Properties;

class TentFilter : public ReconstructionFilter {
 public:
  explicit TentFilter(float radius = 1.0f) : radius_(radius) {}
  float radius() const override { return radius_; }
  // The normalised filter, i.e. the density of sample(): (1 - |x|/r)(1 - |y|/r) / r^2.
  float eval(Vec2 offset) const override;
  Vec2 sample(Vec2 u) const override;

 private:
  float radius_;
  float evalAxis(float x) const;
  float sampleAxis(float u) const;
};

// <rfilter type="tent">: radius (1).
std::shared_ptr<Object> makeTentFilter(const Properties& props);

}  // namespace columba
