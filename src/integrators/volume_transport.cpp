#include "integrators/volume_transport.h"

#include "media/majorant_tracking.h"

namespace columba {

namespace {
// Bounds the surfaces one shadow ray passes through, as Scene::traceThrough does.
constexpr int kMaxShadowLayers = 256;
// Ratio tracking plays Russian roulette once its estimate falls below this, surviving with 1 - q.
constexpr float kRouletteBelow = 0.05f, kRouletteQ = 0.75f;

// Scales the ratios by the majorant transmittance of the stretch a walk passed without stopping,
// which the hero passed with probability tMaj[0]. False where that probability is 0.
bool passStretch(const Spectrum& tMaj, TrackedTransmittance& tr) {
  if (!(tMaj[0] > 0.0f)) return false;
  const Spectrum ratio = tMaj / tMaj[0];
  tr.T *= ratio;
  tr.rU *= ratio;
  tr.rL *= ratio;
  return true;
}
}  // namespace

void ratioTrack(const Medium& medium, const Ray& ray, const Wavelengths& wl, PCG32& rng, TrackedTransmittance& tr) {
  const Spectrum tMaj =
      trackMajorant(medium, ray, wl, rng,
                    [&](const Vec3&, const MediumCoefficients& c, const Spectrum& sigmaMaj, const Spectrum& tMaj) {
                      const Spectrum sigmaN = nullCoefficient(sigmaMaj, c.sigmaT);
                      // The hero drew this collision with density tMaj[0] sigmaMaj[0]; a lane following the path
                      // would have passed it as null with sigma_n / sigma_maj of that.
                      const float pdf = tMaj[0] * sigmaMaj[0];
                      tr.T *= tMaj * sigmaN / pdf;
                      tr.rL *= tMaj * sigmaMaj / pdf;
                      tr.rU *= tMaj * sigmaN / pdf;
                      const Spectrum estimate = tr.T / (tr.rL + tr.rU).average();
                      if (estimate.maxValue() < kRouletteBelow) {
                        if (rng.nextFloat() < kRouletteQ)
                          tr.T = Spectrum(0.0f);
                        else
                          tr.T /= 1.0f - kRouletteQ;
                      }
                      return !tr.T.isZero();
                    });
  if (tr.T.isZero() || !passStretch(tMaj, tr)) tr.T = Spectrum(0.0f);
}

TrackedTransmittance shadowTransmittance(const Scene& scene, Ray ray, const Medium* medium, const Wavelengths& wl,
                                         PCG32& rng, uint64_t& rays) {
  TrackedTransmittance tr;
  const Vec3 dir = normalize(ray.d);
  for (int layer = 0; layer < kMaxShadowLayers; ++layer) {
    ++rays;
    const std::optional<SurfaceInteraction> hit = scene.intersect(ray);
    if (medium) {
      Ray inside = ray;
      if (hit) inside.tmax = hit->t;
      ratioTrack(*medium, inside, wl, rng, tr);
      if (tr.T.isZero()) return tr;
    }
    if (!hit) return tr;
    const BSDF& bsdf = *hit->shape->bsdf;
    if (!bsdf.hasPassThrough() || hit->shape->emitter) {
      tr.T = Spectrum(0.0f);
      return tr;
    }
    tr.T *= bsdf.passThrough(hit->bsdfContext(), hit->shading.toLocal(-dir), wl);
    if (tr.T.isZero()) return tr;
    medium = hit->shape->mediumToward(hit->ng, dir, medium);
    // Continue from just beyond the surface toward the same end point.
    Ray next = hit->spawnRay(dir);
    if (std::isfinite(ray.tmax)) {
      next.d = ray.at(ray.tmax) - next.o;
      next.tmax = 1.0f;
      if (dot(next.d, dir) <= 0.0f) return tr;
    }
    ray = next;
  }
  tr.T = Spectrum(0.0f);
  return tr;
}

}  // namespace columba
