/*! plugin phase blendphase
A blend of two nested phase functions: (1 − weight) times the first plus weight times the second (their order is the order of the nested `<phase>` elements). A direction is drawn from one of the two, chosen with those probabilities, and its density is the blend's.
Mitsuba 3: the same parameter and default; a textured weight is not taken (a number only).
| parameter | type | default | meaning | Mitsuba 3 |
| weight | float | 0.5 | the second phase function's share, 0 to 1 | float or texture |
*/
#include "media/blend_phase.h"

#include <string>

#include "core/error.h"

namespace columba {

float BlendPhase::eval(const Vec3& wi, const Vec3& wo) const {
  return (1.0f - weight_) * first_->eval(wi, wo) + weight_ * second_->eval(wi, wo);
}

float BlendPhase::pdf(const Vec3& wi, const Vec3& wo) const {
  return (1.0f - weight_) * first_->pdf(wi, wo) + weight_ * second_->pdf(wi, wo);
}

std::optional<PhaseSample> BlendPhase::sample(const Vec3& wi, Vec2 u) const {
  // u.x chooses the component and is stretched back to [0, 1) for it.
  const bool second = u.x < weight_;
  const Vec2 uComponent(second ? u.x / weight_ : (u.x - weight_) / (1.0f - weight_), u.y);
  std::optional<PhaseSample> s = (second ? second_ : first_)->sample(wi, uComponent);
  if (!s) return std::nullopt;
  s->pdf = pdf(wi, s->wo);
  return s;
}

std::shared_ptr<Object> makeBlendPhase(const Properties& props) {
  auto nested = props.children<PhaseFunction>();
  if (nested.size() != 2)
    throw InputError(props.location,
                     "'blendphase' takes two nested phase functions, not " + std::to_string(nested.size()));
  const float weight = props.getFloat("weight", 0.5f);
  if (!(weight >= 0.0f && weight <= 1.0f))
    throw props.error("weight", "must lie in [0, 1], not " + std::to_string(weight));
  return std::make_shared<BlendPhase>(nested[0], nested[1], weight);
}

}  // namespace columba
