#pragma once
// The tent filter (Mitsuba's `tent`): on each axis a triangle falling linearly from the pixel's
// centre to zero at `radius` pixels (1 by default).
#include <memory>
#include "film/reconstruction_filter.h"

namespace columba {

class Properties;

class TentFilter : public ReconstructionFilter {
 public:
  explicit TentFilter(float radius = 1.0f) : radius_(radius) {}
  float radius() const override { return radius_; }
  // (1 - |x| / r) / r within the radius.
  float eval(float offset) const override;

 private:
  float radius_;
};

// <rfilter type="tent">: its parameters are in docs/reference/rfilters.md.
std::shared_ptr<Object> makeTentFilter(const Properties& props);

}  // namespace columba
