#pragma once
// `blendphase`: (1 - weight) times the first nested phase function plus weight times the second,
// e.g. aerosols' forward scattering within a Rayleigh atmosphere. A sample comes from one of the
// two, chosen with those probabilities, and its density is the mixture's.
#include <memory>
#include "core/properties.h"
#include "media/phase_function.h"

namespace columba {

class BlendPhase final : public PhaseFunction {
 public:
  // weight in [0, 1].
  BlendPhase(std::shared_ptr<const PhaseFunction> first, std::shared_ptr<const PhaseFunction> second, float weight)
      : first_(std::move(first)), second_(std::move(second)), weight_(weight) {}
  float eval(const Vec3& wi, const Vec3& wo) const override;
  float pdf(const Vec3& wi, const Vec3& wo) const override;
  std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const override;

 private:
  std::shared_ptr<const PhaseFunction> first_, second_;
  float weight_;
};

std::shared_ptr<Object> makeBlendPhase(const Properties& props);

}  // namespace columba
