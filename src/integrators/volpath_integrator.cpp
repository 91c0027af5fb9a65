/*! plugin integrator volpath volpathmis
Mitsuba's volumetric path tracers: paths through participating media (`homogeneous`, `heterogeneous`) bounded by shapes (their `interior` and `exterior`, across null, dielectric and other interfaces) and around a sensor that sits in one. In a medium, collisions are drawn against the medium's majorant for the path's hero wavelength (delta tracking: a collision is real with probability σ_t / majorant, otherwise null); at a real one the path scatters by the phase function, with its albedo as weight. Every scattering vertex, in a medium or on a surface, samples an emitter, whose light is attenuated by the transmittance of the media and null surfaces on the way (ratio tracking); emitter and BSDF or phase samples are combined by multiple importance sampling, and so are the path's four wavelengths, each as if it had been the hero (the balance heuristic over their densities), so that media whose extinction varies with the wavelength are not noisy in the lanes the hero does not follow. Both names are the same integrator. A scene without media (no shape bounds one, the sensor sits in none) is rendered by the plain path tracer with the same parameters (its default `strategy` and `emitter_candidates`), bit for bit, without any medium bookkeeping.
Mitsuba 3: the same parameters and defaults, and the same meaning of depth (medium and surface scattering vertices count, null interfaces do not); emitter and BSDF samples are weighed by the balance heuristic over all four wavelengths (Mitsuba's `volpath` weighs directions by the power heuristic and wavelengths not at all, its `volpathmis` as here); a camera ray that passes a hidden emitter at depth 0 stops there instead of passing through; `timeout` does not stop the render.
uses: passes
| parameter | type | default | meaning | Mitsuba 3 |
| max_depth | integer | -1 | the longest path, in segments; -1 is unlimited, 1 shows the emitters seen directly only; below -1 is an error | same |
| rr_depth | integer | 5 | the depth from which Russian roulette ends paths (with probability 1 − min(throughput, 0.95)); at least 1 | same |
| hide_emitters | boolean | false | emitters seen directly by the camera are black | same |
*/
#include "integrators/volpath_integrator.h"

#include <cmath>
#include <utility>

#include "integrators/direct_light.h"
#include "media/majorant_tracking.h"

namespace columba {

namespace {
// Bounds the pass-through steps of one path, as the path integrator does.
constexpr int kMaxPassThroughSteps = 1024;

// What a path keeps besides its radiance: the throughput and the spectral-MIS ratios
// (integrators/volume_transport.h). rL is the ratio for the last segment drawn by emitter sampling,
// without the emitter's density, which is known only when an emitter is hit.
struct PathState {
  Spectrum beta{1.0f}, rU{1.0f}, rL{1.0f};
  void scale(const Spectrum& ratio) {
    beta *= ratio;
    rU *= ratio;
    rL *= ratio;
  }
};

// Next-event estimation from a vertex at `p`: an emitter sample, `scatter(direction)` the vertex's
// value toward it and its density (BSDF or phase function), `spawn(direction, distance)` the shadow
// ray and the medium it starts in. The balance heuristic over emitter and scattering samples and
// over the lanes as hero.
template <typename Scatter, typename Spawn>
Spectrum emitterSample(const Scene& scene, const Vec3& p, Vec2 u, const Wavelengths& wl, const PathState& path,
                       PCG32& rng, uint64_t& rays, Scatter&& scatter, Spawn&& spawn) {
  float pmf = 0.0f;
  const Emitter* emitter = scene.sampleEmitter(u.x, &pmf);
  if (!emitter) return Spectrum(0.0f);
  const std::optional<EmitterSample> es = emitter->sample(p, u, wl);
  if (!es || !(es->pdf > 0.0f) || es->radiance.isZero()) return Spectrum(0.0f);
  const BSDFEvalPdf f = scatter(es->direction);
  if (f.value.isZero()) return Spectrum(0.0f);
  const auto [shadow, medium] = spawn(es->direction, es->distance);
  const TrackedTransmittance tr = shadowTransmittance(scene, shadow, medium, wl, rng, rays);
  if (tr.T.isZero()) return Spectrum(0.0f);
  const Spectrum rLight = path.rU * tr.rL * (es->pdf * pmf);
  const Spectrum rScatter = path.rU * tr.rU * f.pdf;
  const Spectrum densities = emitter->isDelta() ? rLight : rLight + rScatter;
  return path.beta * f.value * tr.T * es->radiance / densities.average();
}

// Russian roulette from rr_depth on the throughput as the lanes' mixture estimates it. False: the
// path ends.
bool survivesRoulette(PathState& path, int depth, int rrDepth, Sampler& sampler) {
  if (depth < rrDepth) return true;
  const float q = std::min((path.beta / path.rU.average()).maxValue(), 0.95f);
  if (sampler.get1D() >= q) return false;
  path.beta /= q;
  return true;
}
}  // namespace

Spectrum VolumetricPathIntegrator::radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                                            uint64_t& rays) const {
  if (!scene.hasMedia()) return surfacesOnly_->radiance(scene, ray, sampler, wl, rays);
  return radianceInMedia(scene, ray, sampler, wl, rays);
}

Spectrum VolumetricPathIntegrator::radianceInMedia(const Scene& scene, const Ray& cameraRay, Sampler& sampler,
                                                   const Wavelengths& wl, uint64_t& rays) const {
  const int maxDepth = surfacesOnly_->maxDepth(), rrDepth = surfacesOnly_->rrDepth();
  // Walks through media take a varying count of random numbers: they come from a generator seeded
  // by the sampler, so that the sampler's dimensions stay those of the path's vertices.
  const float seedA = sampler.get1D(), seedB = sampler.get1D();
  PCG32 rng(hashCombine(uint64_t(double(seedA) * 0x1p53), uint64_t(double(seedB) * 0x1p53)));

  Spectrum L(0.0f);
  PathState path;
  Ray ray = cameraRay;
  const Medium* medium = scene.sensor().medium();
  int depth = 0, passThroughSteps = 0;
  bool deltaBounce = true;  // the camera, like a delta vertex, takes no MIS weight
  Vec3 prevP;
  while (true) {
    ++rays;
    const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    const Vec3 dir = normalize(ray.d);

    if (medium) {
      // Delta tracking up to the surface: stop at a real collision, pass null ones.
      Ray inside = ray;
      if (hit) inside.tmax = hit->t;
      std::optional<Vec3> scatterAt;
      const Spectrum tMaj = trackMajorant(
          *medium, inside, wl, rng,
          [&](const Vec3& p, const MediumCoefficients& c, const Spectrum& sigmaMaj, const Spectrum& tMaj) {
            if (rng.nextFloat() < c.sigmaT[0] / sigmaMaj[0]) {
              // Real: the hero drew it with density tMaj[0] sigma_t[0]; it scatters sigma_s of it.
              const float pdf = tMaj[0] * c.sigmaT[0];
              path.beta *= tMaj * c.sigmaS / pdf;
              path.rU *= tMaj * c.sigmaT / pdf;
              scatterAt = p;
              return false;
            }
            const Spectrum sigmaN = nullCoefficient(sigmaMaj, c.sigmaT);
            const float pdf = tMaj[0] * sigmaN[0];
            path.beta *= tMaj * sigmaN / pdf;
            path.rU *= tMaj * sigmaN / pdf;
            // Emitter sampling passes every tentative collision (ratio tracking).
            path.rL *= tMaj * sigmaMaj / pdf;
            return !path.beta.isZero() && !path.rU.isZero();
          });
      if (path.beta.isZero() || !path.beta.isFinite()) break;
      if (scatterAt) {
        if (maxDepth >= 0 && depth + 1 >= maxDepth) break;
        const Vec3 p = *scatterAt;
        const PhaseFunction& phase = medium->phase();
        L += emitterSample(
            scene, p, sampler.get2D(), wl, path, rng, rays,
            [&](const Vec3& d) {
              return BSDFEvalPdf{Spectrum(phase.eval(-dir, d)), phase.pdf(-dir, d)};
            },
            [&](const Vec3& d, float distance) {
              const bool finite = std::isfinite(distance);
              return std::pair(Ray{p, finite ? d * distance : d, 0.0f, finite ? 1.0f - 1e-4f : INFINITY}, medium);
            });
        const std::optional<PhaseSample> ps = phase.sample(-dir, sampler.get2D());
        if (!ps || !(ps->pdf > 0.0f)) break;
        path.beta *= phase.eval(-dir, ps->wo) / ps->pdf;
        path.rL = path.rU / ps->pdf;
        ray = Ray{p, ps->wo};
        deltaBounce = false;
        prevP = p;
        if (!survivesRoulette(path, ++depth, rrDepth, sampler)) break;
        continue;
      }
      if (!(tMaj[0] > 0.0f)) break;
      path.scale(tMaj / tMaj[0]);
    }

    if (!(depth == 0 && surfacesOnly_->hidesEmitters())) {
      const EmitterHit seen = emitterSeenAlong(scene, prevP, dir, hit, wl);
      if (!seen.radiance.isZero()) {
        const Spectrum densities = deltaBounce ? path.rU : path.rU + path.rL * seen.lightPdf;
        L += path.beta * seen.radiance / densities.average();
      }
    }
    if (!hit) break;

    const BSDF& bsdf = *hit->shape->bsdf;
    const BSDFContext ctx = hit->bsdfContext();
    const Vec3 wi = hit->shading.toLocal(-dir);
    const float uComponent = sampler.get1D();
    const Vec2 uDirection = sampler.get2D();
    const std::optional<BSDFSample> bs = bsdf.sample(ctx, wi, wl, uComponent, uDirection);
    if (bs && bs->passThrough) {
      // The ray goes on as if the surface were not there, into the medium behind it: no vertex.
      path.beta *= bs->weight;
      if (path.beta.isZero() || ++passThroughSteps > kMaxPassThroughSteps) break;
      medium = hit->shape->mediumToward(hit->ng, dir, medium);
      ray = hit->spawnRay(dir);
      continue;
    }
    if (maxDepth >= 0 && depth + 1 >= maxDepth) break;
    if (!bsdf.isDeltaOnly())
      L += emitterSample(
          scene, hit->p, sampler.get2D(), wl, path, rng, rays,
          [&](const Vec3& d) {
            const Vec3 wo = hit->shading.toLocal(d);
            return BSDFEvalPdf{bsdf.eval(ctx, wi, wo, wl), bsdf.pdf(ctx, wi, wo, wl)};
          },
          [&](const Vec3& d, float distance) {
            Ray shadow = std::isfinite(distance) ? hit->spawnRayTo(hit->p + d * distance) : hit->spawnRay(d);
            return std::pair(shadow, hit->shape->mediumToward(hit->ng, d, medium));
          });
    if (!bs) break;
    path.beta *= bs->weight;
    if (path.beta.isZero() || !path.beta.isFinite()) break;
    const Vec3 wo = hit->shading.toWorld(bs->wo);
    medium = hit->shape->mediumToward(hit->ng, wo, medium);
    ray = hit->spawnRay(wo);
    deltaBounce = bs->delta;
    if (!bs->delta) path.rL = path.rU / bs->pdf;
    prevP = hit->p;
    if (!survivesRoulette(path, ++depth, rrDepth, sampler)) break;
  }
  return L;
}

std::shared_ptr<Object> makeVolumetricPathIntegrator(const Properties& props) {
  return std::make_shared<VolumetricPathIntegrator>(std::dynamic_pointer_cast<const PathIntegrator>(
      makePathIntegratorWith(props, PathIntegrator::Strategy::MIS, PathIntegrator::kAutomatic)));
}

}  // namespace columba
