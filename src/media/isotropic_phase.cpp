/*! plugin phase isotropic
Light is scattered equally into every direction: the phase function is 1 / (4π) per steradian, and directions are drawn uniformly over the sphere.
Mitsuba 3: as Mitsuba 3's `isotropic`.
*/
#include "media/isotropic_phase.h"

#include "core/sampling.h"

namespace columba {

float IsotropicPhase::eval(const Vec3&, const Vec3&) const { return uniformSpherePdf(); }

std::optional<PhaseSample> IsotropicPhase::sample(const Vec3&, Vec2 u) const {
  return PhaseSample{sampleUniformSphere(u), uniformSpherePdf()};
}

std::shared_ptr<Object> makeIsotropicPhase(const Properties&) { return std::make_shared<IsotropicPhase>(); }

}  // namespace columba
