/*! plugin integrator ptracer
A particle tracer (light tracing). Each sample starts a path on an emitter (an emitter chosen uniformly; a cosine-weighted ray from a point of an area light; within a spot's cone, with its texture; through a point of a projector's image chosen uniformly; from the disk of the scene's bounding sphere facing a directional, constant or environment light), follows it through the BSDFs and connects every surface vertex to the camera, splatting what the camera sees of it through the film's filter. Unless `hide_emitters`, it also connects a point of an area light, or a direction of a light at infinity, to the camera, for the emitters seen directly. The camera's importance is 1 / (A cos³θ) per solid angle (A: the image plane's area at unit distance), so the image equals `path`'s in expectation, for every filter.

The film's width × height × sample count light samples are rendered (the crop window's pixels). It renders through the `perspective`, `thinlens` and `orthographic` sensors (an orthographic camera sees lights at infinity along one direction only, which no light sample finds, so such scenes must hide emitters); other sensors are an error naming the integrator's line. Splats cross pixels, so the samples are cut into blocks fixed by the film and the sample count, each splatting into a buffer of its own, summed in block order: images are bit-identical for any thread count. Renders split into `--part` or `--pass` pieces, adaptive sampling and spectral output are refused. Light is scattered at each vertex with the BSDF's arguments as camera paths pass them (toward the camera's side first), so BSDFs that are not reciprocal, the barbule BSDF among them, give the path tracer's image (with Veach's correction for shading normals); a delta sample keeps its own weight, so a dielectric's (η_i/η_t)² scaling of refracted radiance is left out, which cancels along paths between a light and a camera in the same medium.
Mitsuba 3: as Mitsuba 3's `ptracer`, with the same depth parameters and defaults; `timeout` does not stop the render.
uses: passes
| parameter | type | default | meaning | Mitsuba 3 |
| max_depth | integer | -1 | the longest path, counted as in `path` (-1: unlimited; 1: the emitters seen directly only) | same |
| rr_depth | integer | 5 | the depth from which Russian roulette ends paths; at least 1 | same |
| hide_emitters | boolean | false | no emitter is seen directly by the camera | same |
*/
#include "integrators/particle_tracer_integrator.h"

#include "integrators/integrator.h"
#include "scene/scene.h"

namespace columba {

namespace {
// Bounds the pass-through steps of one path, as `path` does.
constexpr int kMaxPassThroughSteps = 1024;

// The adjoint BSDF's factor for shading normals (Veach 1997, p. 155) for light arriving from
// `toLight` and leaving toward `out` (world, with their shading-frame versions `wi` and `wo`):
// |cos_s(wi) cos_g(wo)| / |cos_s(wo) cos_g(wi)|. 0 where a shading normal would let light leak
// through the surface (a direction on different sides for the two normals).
float shadingNormalCorrection(const SurfaceInteraction& hit, const Vec3& toLight, const Vec3& wi, const Vec3& out,
                              const Vec3& wo) {
  const float geometricIn = dot(hit.ng, toLight), geometricOut = dot(hit.ng, out);
  if (!(geometricIn * wi.z > 0.0f) || !(geometricOut * wo.z > 0.0f)) return 0.0f;
  return std::abs(wi.z * geometricOut) / std::abs(wo.z * geometricIn);
}

// The weight of light arriving from `wi` and leaving along the sampled direction: the sample drew
// its direction as camera paths do, weighted f(wi, wo) |cos wo| / pdf, where light leaving along
// wo takes f(wo, wi). The two differ for BSDFs that are not reciprocal (the barbule BSDF). A delta
// or pass-through sample keeps its weight (a mirror, and a straight line through gaps, are the
// same both ways).
Spectrum adjointWeight(const BSDF& bsdf, const BSDFContext& ctx, const Vec3& wi, const BSDFSample& bs,
                       const Wavelengths& wl) {
  if (bs.delta || bs.passThrough) return bs.weight;
  return bsdf.eval(ctx, bs.wo, wi, wl) * (absCosTheta(bs.wo) / (absCosTheta(wi) * bs.pdf));
}
}  // namespace

void ParticleTracerIntegrator::checkScene(const Scene& scene) const {
  const Sensor& sensor = scene.sensor();
  if (!sensor.hasImportance())
    throw InputError(where_,
                     "ptracer connects light to the sensor, which needs its importance: it renders through "
                     "perspective, thinlens and orthographic sensors only (use 'path' for this sensor)");
  if (!hideEmitters_ && maxDepth_ != 0 && !scene.infiniteEmitters().empty() && !sensor.hasImportanceFromDirections())
    throw InputError(where_,
                     "ptracer cannot show lights at infinity seen directly through this sensor (an orthographic "
                     "camera sees them along a single direction, which no light sample finds): set hide_emitters "
                     "or use 'path'");
}

void ParticleTracerIntegrator::trace(const Scene& scene, Sampler& sampler, const Wavelengths& wl, FilmSplats& splats,
                                     uint64_t& rays) const {
  if (maxDepth_ != 0 && !hideEmitters_) splatVisibleEmitter(scene, sampler, wl, splats, rays);
  if (maxDepth_ < 0 || maxDepth_ > 1) traceLightPath(scene, sampler, wl, splats, rays);
}

// Delta lights are never seen directly (no camera ray hits them), as in `path`.
void ParticleTracerIntegrator::splatVisibleEmitter(const Scene& scene, Sampler& sampler, const Wavelengths& wl,
                                                   FilmSplats& splats, uint64_t& rays) const {
  float uChoice = sampler.get1D(), pmf = 0.0f;
  const Vec2 uEmitter = sampler.get2D(), uSensor = sampler.get2D();
  const Emitter* emitter = scene.sampleEmitter(uChoice, &pmf);
  if (!emitter || emitter->isDelta()) return;
  const Sensor& sensor = scene.sensor();
  if (emitter->isInfinite()) {
    // A direction toward the light, from anywhere (at infinity the point does not matter).
    std::optional<EmitterSample> toLight = emitter->sample(scene.boundingSphere().centre, uEmitter, wl);
    if (!toLight || !(toLight->pdf > 0.0f)) return;
    std::optional<ImportanceSample> is = sensor.sampleImportanceFrom(toLight->direction, uSensor);
    if (!is) return;
    Spectrum tr = scene.transmittance(Ray{is->rayStart, toLight->direction}, wl, rays);
    if (tr.isZero()) return;
    splats.add(is->filmPosition, toLight->radiance * tr * (is->weight / (toLight->pdf * pmf)));
    return;
  }
  std::optional<PositionSample> ps = emitter->samplePosition(uEmitter);
  if (!ps) return;
  std::optional<ImportanceSample> is = sensor.sampleImportance(ps->p, uSensor);
  if (!is) return;
  const SurfaceInteraction at = ps->interaction();
  const Vec3 toSensor = normalize(is->origin - ps->p);
  const Spectrum emitted = emitter->radianceAt(at, toSensor, wl);
  if (emitted.isZero()) return;
  Spectrum tr = scene.transmittance(at.spawnRayTo(is->rayStart), wl, rays);
  if (tr.isZero()) return;
  const float cosine = std::abs(dot(ps->n, toSensor));
  splats.add(is->filmPosition, emitted * tr * (cosine * is->weight / (ps->pdfArea * pmf)));
}

void ParticleTracerIntegrator::connectToSensor(const Scene& scene, const SurfaceInteraction& hit, const Vec3& toLight,
                                               const Spectrum& beta, Vec2 u, const Wavelengths& wl, FilmSplats& splats,
                                               uint64_t& rays) const {
  std::optional<ImportanceSample> is = scene.sensor().sampleImportance(hit.p, u);
  if (!is) return;
  const Vec3 toSensor = normalize(is->origin - hit.p);
  const Vec3 wi = hit.shading.toLocal(toLight), wo = hit.shading.toLocal(toSensor);
  const float correction = shadingNormalCorrection(hit, toLight, wi, toSensor, wo);
  if (correction == 0.0f) return;
  // The light scattered toward the sensor: f(wo, wi), the sensor's direction in the camera's place,
  // so BSDFs that are not reciprocal (the barbule BSDF) scatter as they do for camera paths. eval
  // gives it times |cos wi|; the adjoint's cosine is |cos wo|.
  const Spectrum f = hit.shape->bsdf->eval(hit.bsdfContext(), wo, wi, wl) * (absCosTheta(wo) / absCosTheta(wi));
  if (f.isZero()) return;
  const Spectrum tr = scene.transmittance(hit.spawnRayTo(is->rayStart), wl, rays);
  if (tr.isZero()) return;
  splats.add(is->filmPosition, beta * f * tr * (correction * is->weight));
}

void ParticleTracerIntegrator::traceLightPath(const Scene& scene, Sampler& sampler, const Wavelengths& wl,
                                              FilmSplats& splats, uint64_t& rays) const {
  float uChoice = sampler.get1D(), pmf = 0.0f;
  const Vec2 uPosition = sampler.get2D(), uDirection = sampler.get2D();
  const Emitter* emitter = scene.sampleEmitter(uChoice, &pmf);
  if (!emitter) return;
  std::optional<EmitterRaySample> start = emitter->sampleRay(uPosition, uDirection, wl, scene.boundingSphere());
  if (!start) return;
  Spectrum beta = start->weight / pmf;
  if (beta.isZero() || !beta.isFinite()) return;
  Ray ray = start->ray;
  // `depth`: the path's segments so far; connecting a vertex to the sensor adds one.
  int depth = 1, passThroughSteps = 0;
  while (maxDepth_ < 0 || depth < maxDepth_) {
    ++rays;
    std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (!hit) break;
    const Vec3 toLight = -normalize(ray.d);
    connectToSensor(scene, *hit, toLight, beta, sampler.get2D(), wl, splats, rays);

    const float uComponent = sampler.get1D();
    const Vec2 u = sampler.get2D();
    const Vec3 wi = hit->shading.toLocal(toLight);
    std::optional<BSDFSample> bs = hit->shape->bsdf->sample(hit->bsdfContext(), wi, wl, uComponent, u);
    if (!bs) break;
    const Vec3 out = hit->shading.toWorld(bs->wo);
    beta *= adjointWeight(*hit->shape->bsdf, hit->bsdfContext(), wi, *bs, wl) *
            shadingNormalCorrection(*hit, toLight, wi, out, bs->wo);
    if (beta.isZero() || !beta.isFinite()) break;
    ray = hit->spawnRay(out);
    if (bs->passThrough) {
      // The ray goes on as if the surface were not there: no bounce.
      if (++passThroughSteps > kMaxPassThroughSteps) break;
      continue;
    }
    ++depth;
    if (depth > rrDepth_) {
      const float q = std::min(beta.maxValue(), 0.95f);
      if (sampler.get1D() >= q) break;
      beta /= q;
    }
  }
}

std::shared_ptr<Object> makeParticleTracerIntegrator(const Properties& props) {
  int maxDepth = props.getInt("max_depth", -1), rrDepth = props.getInt("rr_depth", 5);
  if (maxDepth < -1) throw props.error("max_depth", "max_depth must be -1 (unlimited) or non-negative");
  if (rrDepth < 1) throw props.error("rr_depth", "rr_depth must be at least 1");
  readMitsubaPassParameters(props);
  return std::make_shared<ParticleTracerIntegrator>(maxDepth, rrDepth, props.getBool("hide_emitters", false),
                                                    props.location);
}

}  // namespace columba
