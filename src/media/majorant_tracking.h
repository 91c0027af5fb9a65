#pragma once
// Tracking along a ray through a medium against its majorant: tentative collisions are drawn at
// the rate sigma_maj of the path's hero wavelength (lane 0), and at each the caller decides what
// happens (a real collision, a null one, absorption). Delta tracking and ratio tracking are both
// built on it (integrators/volume_transport.h).
#include <algorithm>
#include <cmath>
#include "core/rng.h"
#include "media/medium.h"

namespace columba {

// exp(-sigma * distance) per lane, 1 where sigma is 0 (whatever the distance, infinite included).
inline Spectrum majorantTransmittance(const Spectrum& sigma, float distance) {
  Spectrum t;
  for (int k = 0; k < kSpectrumSamples; ++k) t[k] = sigma[k] > 0.0f ? std::exp(-sigma[k] * distance) : 1.0f;
  return t;
}

// The null-collision coefficient sigma_n = sigma_maj - sigma_t per lane, 0 where rounding puts
// sigma_t above the majorant.
inline Spectrum nullCoefficient(const Spectrum& sigmaMaj, const Spectrum& sigmaT) {
  Spectrum sigmaN = sigmaMaj - sigmaT;
  for (int k = 0; k < kSpectrumSamples; ++k) sigmaN[k] = std::max(sigmaN[k], 0.0f);
  return sigmaN;
}

// At most this many tentative collisions along one ray: a grid whose largest value is huge beside
// the rest (a hostile or broken file) would otherwise walk through ~sigma_maj x length null
// collisions, which can be forever. Past it the light is taken as absorbed: a walk that long has a
// majorant optical depth of about a million, where nothing gets through anyway.
inline constexpr int kMostTentativeCollisions = 1 << 20;

// Walks `ray` (from ray.tmin to ray.tmax; d need not be unit length) through `medium`. At each
// tentative collision calls visit(p, coefficients at p, sigma_maj, T_maj), T_maj being the
// majorant transmittance since the previous collision (or the start); visit returns false to stop
// the walk. Returns the majorant transmittance from the last collision to ray.tmax, 1 when visit
// stopped the walk, or 0 after kMostTentativeCollisions.
template <typename Visit>
Spectrum trackMajorant(const Medium& medium, const Ray& ray, const Wavelengths& wl, PCG32& rng, Visit&& visit) {
  const std::optional<MajorantSegment> segment = medium.majorant(ray, wl);
  if (!segment) return Spectrum(1.0f);
  // Distances along the ray in units of its parameter t.
  const float speed = length(ray.d);
  const Spectrum sigmaMaj = segment->sigmaMaj;
  if (!(sigmaMaj[0] > 0.0f)) return majorantTransmittance(sigmaMaj, (segment->tmax - segment->tmin) * speed);
  float t = segment->tmin;
  for (int collisions = 0;; ++collisions) {
    if (collisions == kMostTentativeCollisions) return Spectrum(0.0f);
    const float step = -std::log(1.0f - rng.nextFloat()) / (sigmaMaj[0] * speed);
    if (!(t + step < segment->tmax)) return majorantTransmittance(sigmaMaj, (segment->tmax - t) * speed);
    t += step;
    const Vec3 p = ray.at(t);
    if (!visit(p, medium.coefficients(p, wl), sigmaMaj, majorantTransmittance(sigmaMaj, step * speed)))
      return Spectrum(1.0f);
  }
}

}  // namespace columba
