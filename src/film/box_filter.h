#pragma once
// The box filter: each sample counts for the pixel it lands in (Mitsuba's `box`, radius 0.5 px).
#include <memory>
#include "film/reconstruction_filter.h"

namespace columba {

class Properties;

class BoxFilter : public ReconstructionFilter {
 public:
  float radius() const override { return 0.5f; }
  // The normalised filter: 1 on the pixel's square, 0 outside.
  float eval(Vec2 offset) const override;
  Vec2 sample(Vec2 u) const override { return {u.x - 0.5f, u.y - 0.5f}; }
};

// <rfilter type="box"/>: no parameters.
std::shared_ptr<Object> makeBoxFilter(const Properties& props);

}  // namespace columba
