#pragma once
// The box filter: each sample counts for the pixel it lands in (Mitsuba's `box`, radius 0.5 px).
#include <memory>
#include "film/reconstruction_filter.h"

namespace columba {

class Properties;

class BoxFilter : public ReconstructionFilter {
 public:
  float radius() const override { return 0.5f; }
  // 1 on [-1/2, 1/2), half-open so that a sample on the border between two pixels counts for one.
  float eval(float offset) const override { return offset >= -0.5f && offset < 0.5f ? 1.0f : 0.0f; }
};

// <rfilter type="box">: its parameters are in docs/reference/rfilters.md.
std::shared_ptr<Object> makeBoxFilter(const Properties& props);

}  // namespace columba
