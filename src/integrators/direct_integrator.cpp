/*! plugin integrator direct
Direct illumination only: at the first surface a camera ray reaches, `emitter_samples` emitter samples and `bsdf_samples` BSDF samples, combined by multiple importance sampling when both are used. Camera rays continue through pass-through surfaces with their transmitted weight. With both kinds of samples a `constant` environment is left to the BSDF samples, as in `path`.
Mitsuba 3: the same parameters and defaults; `timeout` does not stop the render.
uses: passes
| parameter | type | default | meaning | Mitsuba 3 |
| shading_samples | integer | 1 | the default of both `emitter_samples` and `bsdf_samples` | same |
| emitter_samples | integer | `shading_samples` | emitter samples per hit; not negative | same |
| bsdf_samples | integer | `shading_samples` | BSDF samples per hit; not negative | same |
| hide_emitters | boolean | false | emitters seen directly by the camera are black | same |
*/
#include "integrators/direct_integrator.h"

#include "core/sampling.h"
#include "integrators/direct_light.h"

namespace columba {

namespace {
constexpr int kMaxPassThroughLayers = 256;
}  // namespace

Spectrum DirectIntegrator::radiance(const Scene& scene, const Ray& cameraRay, Sampler& sampler, const Wavelengths& wl,
                                    uint64_t& rays) const {
  Spectrum L(0.0f), beta(1.0f);
  Ray ray = cameraRay;
  const float nE = float(emitterSamples_), nB = float(bsdfSamples_);
  for (int layer = 0; layer < kMaxPassThroughLayers; ++layer) {
    ++rays;
    std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    Vec3 dir = normalize(ray.d);
    if (!hideEmitters_) L += beta * emitterSeenAlong(scene, ray.o, dir, hit, wl).radiance;
    if (!hit) break;
    const BSDF& bsdf = *hit->shape->bsdf;
    Vec3 wi = hit->shading.toLocal(-dir);
    // Pass-through is covered by continuing the camera ray below, so BSDF samples need not draw it.
    BSDFContext ctx = hit->bsdfContext();
    ctx.passThroughByCaller = true;
    // With both kinds of samples, emitters that the BSDF samples find as well are left to them.
    const Scene::EmitterSet emitterSet =
        emitterSamples_ > 0 && bsdfSamples_ > 0 && scene.leavesEmittersToBSDFSamples() && bsdf.samplesAllItScatters()
            ? Scene::EmitterSet::BesideBSDFSamples
            : Scene::EmitterSet::All;

    // The pass-through weight is asked for together with the first emitter sample's evaluation, or
    // else with the first BSDF sample.
    std::optional<Spectrum> passThrough;
    for (int i = 0; i < emitterSamples_ && !bsdf.isDeltaOnly(); ++i) {
      std::optional<LightSample> light = sampleLight(scene, *hit, wl, sampler.get2D(), emitterSet);
      if (!light) continue;
      BSDFVertexRequest request;
      request.woLights = &light->woLocal;
      request.woLightCount = 1;
      BSDFEvalPdf toLight;
      request.toLights = &toLight;
      request.lightPdf = bsdfSamples_ > 0 && !light->emitter->isDelta();
      request.passThrough = !passThrough && bsdf.hasPassThrough();
      BSDFVertexQueries queries = bsdf.queryVertex(ctx, wi, wl, request);
      if (request.passThrough) passThrough = queries.passThrough;
      if (auto ds = connectToLight(scene, *hit, *light, toLight, wl, rays)) {
        float w = (ds->deltaLight || bsdfSamples_ == 0) ? 1.0f : powerHeuristic(nE * ds->lightPdf, nB * ds->bsdfPdf);
        L += beta * ds->value * (w / nE);
      }
    }
    for (int i = 0; i < bsdfSamples_; ++i) {
      BSDFVertexRequest request;
      request.sample = true;
      request.uComponent = sampler.get1D();
      request.u = sampler.get2D();
      request.samplePdf = emitterSamples_ > 0;  // for MIS only
      request.passThrough = !passThrough && bsdf.hasPassThrough();
      BSDFVertexQueries queries = bsdf.queryVertex(ctx, wi, wl, request);
      if (request.passThrough) passThrough = queries.passThrough;
      const std::optional<BSDFSample>& bs = queries.sampled;
      // From a BSDF that ignores passThroughByCaller.
      if (!bs || bs->passThrough) continue;
      Vec3 woWorld = hit->shading.toWorld(bs->wo);
      std::optional<SurfaceInteraction> next;
      Spectrum tr = scene.traceThrough(hit->spawnRay(woWorld), wl, rays, next);
      if (tr.isZero()) continue;
      EmitterHit seen = emitterSeenAlong(scene, hit->p, woWorld, next, wl, emitterSet);
      if (seen.radiance.isZero()) continue;
      float w = (bs->delta || emitterSamples_ == 0) ? 1.0f : powerHeuristic(nB * bs->pdf, nE * seen.lightPdf);
      L += beta * bs->weight * tr * seen.radiance * (w / nB);
    }

    if (!bsdf.hasPassThrough()) break;
    beta *= passThrough ? *passThrough : bsdf.passThrough(ctx, wi, wl);
    if (beta.isZero()) break;
    ray = hit->spawnRay(dir);
  }
  return L;
}

std::shared_ptr<Object> makeDirectIntegrator(const Properties& props) {
  int shading = props.getInt("shading_samples", 1);
  int emitterSamples = props.getInt("emitter_samples", shading), bsdfSamples = props.getInt("bsdf_samples", shading);
  if (emitterSamples < 0) throw props.error("emitter_samples", "emitter_samples must not be negative");
  if (bsdfSamples < 0) throw props.error("bsdf_samples", "bsdf_samples must not be negative");
  readMitsubaPassParameters(props);
  return std::make_shared<DirectIntegrator>(emitterSamples, bsdfSamples, props.getBool("hide_emitters", false));
}

}  // namespace columba
