/*! plugin phase rayleigh
Rayleigh scattering, by particles much smaller than the wavelength: 3 (1 + cos² θ) / (16π) per steradian, θ the scattering angle, as much backward as forward. Directions are drawn by inverting its distribution of cos θ exactly (a cubic, solved in closed form). It does not depend on the wavelength here; a medium's σ_t carries the λ⁻⁴ of the sky.
Mitsuba 3: as Mitsuba 3's `rayleigh`.
*/
#include "media/rayleigh_phase.h"

#include <cmath>

namespace columba {

float RayleighPhase::eval(const Vec3& wi, const Vec3& wo) const { return density(-dot(wi, wo)); }

std::optional<PhaseSample> RayleighPhase::sample(const Vec3& wi, Vec2 u) const {
  // The distribution of c = cos theta is (3 c + c^3 + 4) / 8 on [-1, 1]; c^3 + 3 c + (4 - 8 u) = 0
  // has the one real root (Cardano) c = cbrt(z + r) + cbrt(z - r), z = 4 u - 2, r = sqrt(z^2 + 1).
  const float z = 4.0f * u.x - 2.0f, r = std::sqrt(z * z + 1.0f);
  const float cosTheta = std::clamp(std::cbrt(z + r) + std::cbrt(z - r), -1.0f, 1.0f);
  const Vec3 wo = scatteredDirection(wi, cosTheta, u.y);
  return PhaseSample{wo, density(cosTheta)};
}

std::shared_ptr<Object> makeRayleighPhase(const Properties&) { return std::make_shared<RayleighPhase>(); }

}  // namespace columba
