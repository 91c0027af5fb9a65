#include "integrators/direct_light.h"

namespace columba {

std::optional<LightSample> sampleLight(const Scene& scene, const SurfaceInteraction& hit, const Wavelengths& wl, Vec2 u,
                                       Scene::EmitterSet set) {
  LightSample light;
  light.emitter = scene.sampleEmitter(u.x, &light.pmf, set);
  if (!light.emitter) return std::nullopt;
  auto es = light.emitter->sample(hit.p, u, wl);
  if (!es || es->pdf <= 0.0f) return std::nullopt;
  light.sample = *es;
  light.woLocal = hit.shading.toLocal(es->direction);
  return light;
}

std::optional<DirectLightSample> connectToLight(const Scene& scene, const SurfaceInteraction& hit,
                                                const LightSample& light, const BSDFEvalPdf& f, const Wavelengths& wl,
                                                uint64_t& rays) {
  if (f.value.isZero()) return std::nullopt;
  const EmitterSample& es = light.sample;
  Ray shadow =
      std::isfinite(es.distance) ? hit.spawnRayTo(hit.p + es.direction * es.distance) : hit.spawnRay(es.direction);
  Spectrum tr = scene.transmittance(shadow, wl, rays);
  if (tr.isZero()) return std::nullopt;
  DirectLightSample s;
  s.lightPdf = es.pdf * light.pmf;
  s.deltaLight = light.emitter->isDelta();
  s.bsdfPdf = s.deltaLight ? 0.0f : f.pdf;
  s.value = f.value * es.radiance * tr / s.lightPdf;
  return s;
}

float resamplingRatio(const LightSample& light, const Spectrum& f) {
  const float density = light.sample.pdf * light.pmf;
  const float contribution = (f * light.sample.radiance).average();
  return density > 0.0f && contribution > 0.0f ? contribution / density : 0.0f;
}

std::optional<ResampledLight> resampleLights(const float* ratios, int count, float u) {
  float total = 0.0f;
  for (int k = 0; k < count; ++k) total += ratios[k];
  if (!(total > 0.0f)) return std::nullopt;
  // The first candidate whose ratios, summed up to it, pass u of the total.
  float target = u * total, below = 0.0f;
  int chosen = -1;
  for (int k = 0; k < count; ++k) {
    if (!(ratios[k] > 0.0f)) continue;
    chosen = k;
    below += ratios[k];
    if (below > target) break;
  }
  return ResampledLight{chosen, total / float(count) / ratios[chosen]};
}

EmitterHit emitterSeenAlong(const Scene& scene, const Vec3& from, const Vec3& direction,
                            const std::optional<SurfaceInteraction>& hit, const Wavelengths& wl,
                            Scene::EmitterSet set) {
  EmitterHit result;
  if (!hit) {
    for (const Emitter* e : scene.infiniteEmitters()) {
      result.radiance += e->radianceFromDirection(direction, wl);
      result.lightPdf += e->pdfDirection(direction) * scene.emitterPmf(*e, set);
    }
  } else if (const Emitter* e = hit->shape->emitter.get()) {
    result.radiance = e->radianceAt(*hit, -direction, wl);
    if (!result.radiance.isZero()) result.lightPdf = e->pdfHit(from, *hit) * scene.emitterPmf(*e, set);
  }
  return result;
}

}  // namespace columba
