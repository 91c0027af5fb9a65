#include "media/medium.h"

#include <string>

#include "media/isotropic_phase.h"

namespace columba {

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
