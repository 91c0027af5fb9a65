#pragma once
// `isotropic`: light is scattered equally into every direction, 1 / (4 pi) per steradian.
#include "core/properties.h"
#include "media/phase_function.h"

namespace columba {

class IsotropicPhase final : public PhaseFunction {
 public:
  float eval(const Vec3& wi, const Vec3& wo) const override;
  std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const override;
};

std::shared_ptr<Object> makeIsotropicPhase(const Properties& props);

}  // namespace columba
