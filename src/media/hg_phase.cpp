/*! plugin phase hg
The Henyey–Greenstein phase function, (1 − g²) / (4π (1 + g² − 2g cos θ)^{3/2}) with θ the angle between the light's direction of travel before and after scattering; directions are drawn by inverting its distribution of cos θ exactly, in double precision and in terms of 1 ∓ cos θ, so that a lobe narrower than float resolves in cos θ (g = 0.99999) keeps its light.
Mitsuba 3: as Mitsuba 3's `hg`.
| parameter | type | default | meaning | Mitsuba 3 |
| g | float | 0.8 | the mean cosine of the scattering angle: positive scatters forward, negative backward, 0 is isotropic; within (−1, 1) | same |
*/
#include "media/hg_phase.h"

#include <cmath>

#include "core/sampling.h"

namespace columba {

// Near |g| = 1 the lobe is narrower than float resolves in cos theta (at g = 0.99999 its width
// 1 - cos theta is about 5e-11, where float's spacing near 1 is 6e-8), and 1 + g^2 - 2 g cos theta
// cancelled to 0 or below: the sampled light was lost. The density is written as (1 - g)^2 +
// 2 g (1 - cos theta) for g >= 0 and (1 + g)^2 - 2 g (1 + cos theta) below, sums of terms that do
// not cancel, and sampling draws cos theta in double.
float HenyeyGreensteinPhase::density(double oneMinusCos, double onePlusCos) const {
  const double g = g_;
  const double denominator =
      g >= 0.0 ? (1.0 - g) * (1.0 - g) + 2.0 * g * oneMinusCos : (1.0 + g) * (1.0 + g) - 2.0 * g * onePlusCos;
  return float((1.0 - g) * (1.0 + g) / (4.0 * kPiDouble * denominator * std::sqrt(denominator)));
}

float HenyeyGreensteinPhase::eval(const Vec3& wi, const Vec3& wo) const {
  // 1 - cos theta = 1 + wi . wo = |wi + wo|^2 / 2 and 1 + cos theta = |wi - wo|^2 / 2 for unit
  // vectors, each accurate where it is small.
  const Vec3 sum = wi + wo, difference = wi - wo;
  return density(0.5 * double(dot(sum, sum)), 0.5 * double(dot(difference, difference)));
}

std::optional<PhaseSample> HenyeyGreensteinPhase::sample(const Vec3& wi, Vec2 u) const {
  // 1 - cos theta from the inverse of its cumulative distribution; near g = 0 that inverse divides
  // 0 by 0, and the distribution is uniform in cos theta there.
  const double g = g_;
  double oneMinusCos;
  if (std::abs(g) < 1e-3) {
    oneMinusCos = 2.0 * double(u.x);
  } else {
    const double ratio = (1.0 - g) * (1.0 + g) / (1.0 - g + 2.0 * g * double(u.x));
    oneMinusCos = std::clamp((ratio * ratio - (1.0 - g) * (1.0 - g)) / (2.0 * g), 0.0, 2.0);
    // Backward (g < 0) the lobe is at 1 + cos theta near 0: from (1 + g)^2 - ratio^2 there.
    if (g < 0.0) oneMinusCos = 2.0 - std::clamp((ratio * ratio - (1.0 + g) * (1.0 + g)) / (-2.0 * g), 0.0, 2.0);
  }
  const double cosTheta = 1.0 - oneMinusCos;
  const Vec3 wo = scatteredDirection(wi, float(cosTheta), float(std::sqrt(oneMinusCos * (2.0 - oneMinusCos))), u.y);
  // The density of the direction made, as eval gives it: the weight eval / pdf is exactly 1.
  const float pdf = eval(wi, wo);
  if (!(pdf > 0.0f)) return std::nullopt;
  return PhaseSample{wo, pdf};
}

std::shared_ptr<Object> makeHenyeyGreensteinPhase(const Properties& props) {
  const float g = props.getFloat("g", 0.8f);
  if (!(g > -1.0f && g < 1.0f))
    throw props.error("g", "g must lie strictly between -1 and 1, not " + std::to_string(g));
  return std::make_shared<HenyeyGreensteinPhase>(g);
}

}  // namespace columba
