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

// Resampled importance sampling of emitter samples (Talbot, Cline and Egbert 2005): of `count`
// candidates drawn by sampleLight (a failed draw counts, with ratio 0), one is chosen with
// probability proportional to its ratio r = (its unshadowed contribution f Le, averaged over the
// wavelengths) / (its density), and only its shadow ray is traced. Its contribution f Le V / pdf
// times `weight` = mean(r) / r_chosen is an unbiased estimate for any count, and has far less
// variance where f is large for a small part of the emitter (the barbule's narrow R lobe under an
// area light). `u` chooses; nullopt when every ratio is 0.
struct ResampledLight {
  int index = 0;
  float weight = 0.0f;
};
float resamplingRatio(const LightSample& light, const Spectrum& f);
std::optional<ResampledLight> resampleLights(const float* ratios, int count, float u);

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
