#pragma once
// Pixel reconstruction filters, used by filter importance sampling: each camera sample is
// offset from the pixel centre with density proportional to the filter, so it contributes
// to one pixel only with weight 1 (deterministic, no cross-tile splatting). Filters here are
// non-negative.
#include "core/object.h"
#include "core/vector.h"

namespace columba {

class ReconstructionFilter : public Object {
 public:
  virtual float radius() const = 0;
  virtual float eval(Vec2 offset) const = 0;
  // Offset from the pixel centre, distributed as the normalised filter.
  virtual Vec2 sample(Vec2 u) const = 0;
};

}  // namespace columba
