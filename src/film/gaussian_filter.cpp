/*! plugin rfilter gaussian
A Gaussian windowed at 4 standard deviations (the Gaussian minus its value there, clamped at 0), normalised; the default filter of `hdrfilm`.
Mitsuba 3: as Mitsuba 3's `gaussian`; `stddev` is bounded so that the filter's radius reaches the centre of every sample's own pixel and stays within the film's splat reach.
| parameter | type | default | meaning | Mitsuba 3 |
| stddev | float | 0.5 | the standard deviation in pixels, 0.125 to 4.125 | same default, not bounded |
*/
#include "film/gaussian_filter.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include "core/math.h"
#include "core/properties.h"

namespace columba {

GaussianFilter::GaussianFilter(float stddev) : stddev_(stddev), radius_(4.0f * stddev) {
  const double s = stddev_, r = radius_, atRadius = std::exp(-r * r / (2.0 * s * s));
  const double mass = s * std::sqrt(2.0 * kPiDouble) * std::erf(r / (s * std::sqrt(2.0))) - 2.0 * r * atRadius;
  atRadius_ = float(atRadius);
  normalization_ = float(1.0 / mass);
}

float GaussianFilter::eval(float offset) const {
  if (!(std::abs(offset) <= radius_)) return 0.0f;
  return normalization_ * std::max(0.0f, std::exp(-offset * offset / (2.0f * stddev_ * stddev_)) - atRadius_);
}

std::shared_ptr<Object> makeGaussianFilter(const Properties& props) {
  float stddev = props.getFloat("stddev", 0.5f);
  if (!(stddev > 0.0f) || !std::isfinite(stddev)) throw props.error("stddev", "must be a positive number");
  if (!(4.0f * stddev >= kMinFilterRadius))
    throw props.error("stddev",
                      fmt::format("must be at least {} pixels, so that the filter's radius (4 stddev) reaches "
                                  "the centre of the pixel of every sample, not {}",
                                  kMinFilterRadius / 4.0f, stddev));
  if (!(4.0f * stddev <= kMaxFilterRadius))
    throw props.error("stddev", fmt::format("must be at most {} pixels, so that the filter's radius (4 stddev) is at "
                                            "most {}",
                                            kMaxFilterRadius / 4.0f, kMaxFilterRadius));
  return std::make_shared<GaussianFilter>(stddev);
}

}  // namespace columba
