#include "integrators/direct_light.h"

namespace columba {

std::optional<DirectLightSample> sampleDirectLight(const Scene& scene, const SurfaceInteraction& hit, const BSDF& bsdf,
                                                   const Vec3& wiLocal, const Wavelengths& wl, Vec2 u,
                                                   bool needBsdfPdf, uint64_t& rays) {
  float pmf = 0.0f;
  const Emitter* emitter = scene.sampleEmitter(u.x, &pmf);
  if (!emitter) return std::nullopt;
  auto es = emitter->sample(hit.p, u, wl);
  if (!es || es->pdf <= 0.0f) return std::nullopt;
  Vec3 woLocal = hit.shading.toLocal(es->direction);
  bool mis = !emitter->isDelta() && needBsdfPdf;
  BSDFEvalPdf f = mis ? bsdf.evalPdf(hit.bsdfContext, wiLocal, woLocal, wl)
                      : BSDFEvalPdf{bsdf.eval(hit.bsdfContext, wiLocal, woLocal, wl), 0.0f};
  if (f.value.isZero()) return std::nullopt;
  Ray shadow = std::isfinite(es->distance) ? hit.spawnRayTo(hit.p + es->direction * es->distance)
                                           : hit.spawnRay(es->direction);
  Spectrum tr = scene.transmittance(shadow, wl, rays);
  if (tr.isZero()) return std::nullopt;
  DirectLightSample s;
  s.lightPdf = es->pdf * pmf;
  s.deltaLight = emitter->isDelta();
  s.bsdfPdf = f.pdf;
  s.value = f.value * es->radiance * tr / s.lightPdf;
  return s;
}

EmitterHit emitterSeenAlong(const Scene& scene, const Vec3& from, const Vec3& direction,
                            const std::optional<SurfaceInteraction>& hit, const Wavelengths& wl) {
  EmitterHit result;
  if (!hit) {
    for (const Emitter* e : scene.infiniteEmitters()) {
      result.radiance += e->radianceFromDirection(direction, wl);
      result.lightPdf += e->pdfDirection(direction) * scene.emitterPmf();
    }
  } else if (const Emitter* e = hit->shape->emitter.get()) {
    result.radiance = e->radianceAt(*hit, -direction, wl);
    if (!result.radiance.isZero()) result.lightPdf = e->pdfHit(from, *hit) * scene.emitterPmf();
  }
  return result;
}

}  // namespace columba
