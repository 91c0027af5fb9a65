#pragma once
// Next-event estimation shared by the integrators: one emitter sample from a surface point.
#include <optional>
#include "scene/scene.h"

namespace columba {

struct DirectLightSample {
  Spectrum value;         // f * Le * transmittance / lightPdf, before any MIS weight
  float lightPdf = 0.0f;  // solid-angle density including the emitter choice
  float bsdfPdf = 0.0f;   // density of BSDF sampling producing the same direction
  bool deltaLight = false;
};

// Next-event estimation in two steps, so that integrators can ask the BSDF for more at the same
// time: an emitter sample seen from the hit (`u.x` chooses the emitter and, remapped, with `u.y`
// the point on it), then, given the BSDF's value and density toward it, the shadow ray. nullopt
// when nothing was sampled or the contribution is zero (e.g. occluded).
struct LightSample {
  const Emitter* emitter = nullptr;
  EmitterSample sample;
  float pmf = 0.0f;  // probability of choosing `emitter`
  Vec3 woLocal;      // the direction toward it in the hit's shading frame
};
std::optional<LightSample> sampleLight(const Scene& scene, const SurfaceInteraction& hit, const Wavelengths& wl, Vec2 u,
                                       Scene::EmitterSet set);
std::optional<DirectLightSample> connectToLight(const Scene& scene, const SurfaceInteraction& hit,
                                                const LightSample& light, const BSDFEvalPdf& f, const Wavelengths& wl,
                                                uint64_t& rays);

// Radiance of the emitters a ray that left `from` sees at `hit` (or at infinity if there is no
// hit), with the density emitter sampling from `from`, drawing from `set`, would have chosen that
// direction.
struct EmitterHit {
  Spectrum radiance;
  float lightPdf = 0.0f;
};
EmitterHit emitterSeenAlong(const Scene& scene, const Vec3& from, const Vec3& direction,
                            const std::optional<SurfaceInteraction>& hit, const Wavelengths& wl,
                            Scene::EmitterSet set = Scene::EmitterSet::All);

}  // namespace columba
