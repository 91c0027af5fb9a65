/*! plugin rfilter tent
The tent filter: max(0, 1 − |x| / radius) / radius.
Mitsuba 3: as Mitsuba 3's `tent`; `radius` is bounded so that it reaches the centre of every sample's own pixel and stays within the film's splat reach.
| parameter | type | default | meaning | Mitsuba 3 |
| radius | float | 1 | the half-width in pixels, 0.5 to 16.5 | same default, not bounded |
*/
#include "film/tent_filter.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/properties.h"

namespace columba {

float TentFilter::eval(float offset) const { return std::max(0.0f, 1.0f - std::abs(offset) / radius_) / radius_; }

std::shared_ptr<Object> makeTentFilter(const Properties& props) {
  const float radius = props.getFloat("radius", 1.0f);
  if (!(radius > 0.0f) || !std::isfinite(radius))
    throw props.error("radius", "radius must be positive, not " + std::to_string(radius));
  if (!(radius >= kMinFilterRadius))
    throw props.error("radius", fmt::format("radius must be at least {} pixels, so that it reaches the centre of the "
                                            "pixel of every sample, not {}",
                                            kMinFilterRadius, radius));
  if (!(radius <= kMaxFilterRadius))
    throw props.error("radius", fmt::format("radius must be at most {} pixels, not {}", kMaxFilterRadius, radius));
  return std::make_shared<TentFilter>(radius);
}

}  // namespace columba
