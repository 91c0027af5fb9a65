/*! plugin phase hg
The Henyey–Greenstein phase function, (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}) with θ the angle between the light's direction of travel before and after scattering; directions are drawn by inverting its distribution of cos θ exactly.
Mitsuba 3: as Mitsuba 3's `hg`.
| parameter | type | default | meaning | Mitsuba 3 |
| g | float | 0.8 | the mean cosine of the scattering angle: positive scatters forward, negative backward, 0 is isotropic; within (−1, 1) | same |
*/
#include "media/hg_phase.h"

#include <cmath>

#include "core/sampling.h"

namespace columba {

float HenyeyGreensteinPhase::density(float cosTheta) const {
  const float denominator = 1.0f + g_ * g_ - 2.0f * g_ * cosTheta;
  return (1.0f - g_ * g_) / (4.0f * kPi * denominator * std::sqrt(denominator));
}

float HenyeyGreensteinPhase::eval(const Vec3& wi, const Vec3& wo) const { return density(-dot(wi, wo)); }

std::optional<PhaseSample> HenyeyGreensteinPhase::sample(const Vec3& wi, Vec2 u) const {
  // cos theta from the inverse of its cumulative distribution; near g = 0 that inverse divides
  // 0 by 0, and the distribution is uniform in cos theta there.
  float cosTheta;
  if (std::abs(g_) < 1e-3f) {
    cosTheta = 1.0f - 2.0f * u.x;
  } else {
    const float ratio = (1.0f - g_ * g_) / (1.0f - g_ + 2.0f * g_ * u.x);
    cosTheta = std::clamp((1.0f + g_ * g_ - ratio * ratio) / (2.0f * g_), -1.0f, 1.0f);
  }
  const Vec3 wo = scatteredDirection(wi, cosTheta, u.y);
  return PhaseSample{wo, density(cosTheta)};
}

std::shared_ptr<Object> makeHenyeyGreensteinPhase(const Properties& props) {
  const float g = props.getFloat("g", 0.8f);
  if (!(g > -1.0f && g < 1.0f))
    throw props.error("g", "g must lie strictly between -1 and 1, not " + std::to_string(g));
  return std::make_shared<HenyeyGreensteinPhase>(g);
}

}  // namespace columba
