#pragma once
#include <limits>
#include "core/vector.h"

namespace columba {

struct Ray {
  Vec3 o, d;
  float tmin = 0.0f;
  float tmax = std::numeric_limits<float>::infinity();
  Vec3 at(float t) const { return o + d * t; }
};

}  // namespace columba
