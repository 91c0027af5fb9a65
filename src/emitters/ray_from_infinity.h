#pragma once
// Light tracing's rays from lights at infinity (as pbrt and Mitsuba): light arriving from
// direction w crosses the scene's bounding sphere through the disk facing w, so a ray starts on
// that disk, uniform by area, and travels along -w.
#include "emitters/emitter.h"

namespace columba {

// `toLight`: a direction toward the light as the emitter samples it (from any point: at infinity
// the point does not matter), with its radiance and solid-angle density; `uDisk` picks the point
// of the disk.
std::optional<EmitterRaySample> rayFromInfinity(const EmitterSample& toLight, Vec2 uDisk, const SceneSphere& scene);

}  // namespace columba
