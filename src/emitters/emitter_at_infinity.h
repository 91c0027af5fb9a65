#pragma once
// Lights at infinity (directional, constant, envmap) send light tracing's rays alike, as pbrt and
// Mitsuba do: light arriving from direction w crosses the scene's bounding sphere through the
// disk facing w, so a ray starts on that disk, uniform by area, and travels along -w, w drawn as
// the emitter's own sample() draws a direction toward the light (from any point: at infinity the
// point does not matter).
#include "emitters/emitter.h"

namespace columba {

class EmitterAtInfinity : public Emitter {
 public:
  // `uDirection` draws w, `uPosition` the point of the disk.
  std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                            const SceneSphere& scene) const final;
};

}  // namespace columba
