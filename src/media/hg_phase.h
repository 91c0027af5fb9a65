#pragma once
// `hg`: the Henyey-Greenstein phase function, whose one parameter g is the mean cosine of the
// scattering angle (forward scattering for g > 0, backward for g < 0).
#include "core/properties.h"
#include "media/phase_function.h"

namespace columba {

class HenyeyGreensteinPhase final : public PhaseFunction {
 public:
  // |g| < 1.
  explicit HenyeyGreensteinPhase(float g) : g_(g) {}
  float eval(const Vec3& wi, const Vec3& wo) const override;
  std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const override;
  float g() const { return g_; }

 private:
  // The density at angle theta between the light's direction of travel before and after, given
  // as 1 - cos theta and 1 + cos theta (each accurate where it is small).
  float density(double oneMinusCos, double onePlusCos) const;
  float g_;
};

std::shared_ptr<Object> makeHenyeyGreensteinPhase(const Properties& props);

}  // namespace columba
