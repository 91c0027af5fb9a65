#include "film/box_filter.h"

#include <cmath>

namespace columba {

float BoxFilter::eval(Vec2 offset) const {
  return std::abs(offset.x) <= 0.5f && std::abs(offset.y) <= 0.5f ? 1.0f : 0.0f;
}

std::shared_ptr<Object> makeBoxFilter(const Properties&) { return std::make_shared<BoxFilter>(); }

}  // namespace columba
