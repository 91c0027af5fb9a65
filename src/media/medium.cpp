#include "media/medium.h"

#include <string>

#include "media/isotropic_phase.h"

namespace columba {

Medium::Medium(std::shared_ptr<PhaseFunction> phase, const Properties* element) : phase_(std::move(phase)) {
  if (!element) return;
  name_ = " '" + element->type + "'" + (element->id.empty() ? "" : " (id '" + element->id + "')");
  where_ = element->location;
}

void Medium::warnWalkCut(int collisions) const {
  if (warnedWalkCut_.exchange(true)) return;
  warn(where_, "medium" + name_ + ": a ray met " + std::to_string(collisions) +
                   " tentative collisions in it and was taken as absorbed beyond them: the majorant of its "
                   "extinction is far above the extinction there (a few huge values beside small ones); the image is "
                   "darker where this happens");
}

std::shared_ptr<PhaseFunction> mediumPhase(const Properties& props) {
  if (auto phase = props.child<PhaseFunction>()) return phase;
  return makeDefaultPlugin<PhaseFunction>(makeIsotropicPhase, "phase", "isotropic", props.location);
}

float mediumScale(const Properties& props) {
  const float scale = props.getFloat("scale", 1.0f);
  if (!(scale >= 0.0f)) throw props.error("scale", "scale must not be negative, not " + std::to_string(scale));
  return scale;
}

}  // namespace columba
