#include "film/tent_filter.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/properties.h"

namespace columba {

float TentFilter::evalAxis(float x) const { return std::max(0.0f, 1.0f - std::abs(x) / radius_) / radius_; }

float TentFilter::eval(Vec2 offset) const { return evalAxis(offset.x) * evalAxis(offset.y); }

// With s = 1 + x/r, the CDF is s^2 / 2 on the rising half (u < 1/2), mirrored on the falling half.
float TentFilter::sampleAxis(float u) const {
  const float x = u < 0.5f ? std::sqrt(2.0f * u) - 1.0f : 1.0f - std::sqrt(2.0f - 2.0f * u);
  return clampf(x * radius_, -radius_, radius_);
}

Vec2 TentFilter::sample(Vec2 u) const { return {sampleAxis(u.x), sampleAxis(u.y)}; }

std::shared_ptr<Object> makeTentFilter(const Properties& props) {
  const float radius = props.getFloat("radius", 1.0f);
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw props.error("radius", "radius must be positive, not " + std::to_string(radius));
  return std::make_shared<TentFilter>(radius);
}

}  // namespace columba
