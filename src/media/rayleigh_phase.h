#pragma once
// `rayleigh`: scattering by particles much smaller than the wavelength (air molecules),
// 3 (1 + cos^2 theta) / (16 pi) per steradian, as much backward as forward.
#include "core/properties.h"
#include "media/phase_function.h"

namespace columba {

class RayleighPhase final : public PhaseFunction {
 public:
  // The density at cosTheta, the cosine of the scattering angle.
  static float density(float cosTheta) { return 3.0f / (16.0f * kPi) * (1.0f + cosTheta * cosTheta); }

  float eval(const Vec3& wi, const Vec3& wo) const override;
  std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const override;
};

std::shared_ptr<Object> makeRayleighPhase(const Properties& props);

}  // namespace columba
