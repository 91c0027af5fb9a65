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

// At most this many tentative collisions along one ray. The majorant grid keeps a few huge values
// from raising the majorant far from them, but within a cell that also holds thin parts (a value
// of 1e30 beside ones) a walk would still pass ~sigma_maj x length null collisions, which can be
// forever. Past it the light is taken as absorbed, with a warning naming the medium: a walk that
// long has a majorant optical depth of about a million, where nothing gets through anyway.
inline constexpr int kMostTentativeCollisions = 1 << 20;
// At most this many tentative collisions in a row that cannot move t: where a step is below float
// resolution, every collision falls on the same point, and the walk ends there only after
// ~sigma_maj / sigma_t of them (a ray entering a cell of a 1e30 voxel where it weighs nothing).
// Past it the light is taken as absorbed, as past the cap: the majorant's optical depth per float
// step is then over ~1e-7 x sigma_maj x t, far beyond what any light gets through.
inline constexpr int kMostStalledCollisions = 64;

// Walks `ray` (from ray.tmin to ray.tmax; d need not be unit length) through `medium`, segment by
// segment of its majorant. Within a segment the distance to the next tentative collision is
// exponential at the segment's rate sigma_maj (the hero wavelength's, lane 0); one that would pass
// the segment's end is not taken, and drawing starts afresh at the end with the next segment's
// rate: the exponential distribution forgets how far it has come, so this draws collisions with
// the density of the piecewise-constant majorant, exp(-integral of sigma_maj) sigma_maj.
// At each tentative collision calls visit(p, coefficients at p, sigma_maj, T_maj), T_maj being the
// majorant transmittance since the previous collision (or the start); visit returns false to stop
// the walk. Returns the majorant transmittance from the last collision to ray.tmax, 1 when visit
// stopped the walk, or 0 after kMostTentativeCollisions (or kMostStalledCollisions in a row).
template <typename Visit>
Spectrum trackMajorant(const Medium& medium, const Ray& ray, const Wavelengths& wl, PCG32& rng, Visit&& visit) {
  MajorantIterator segments = medium.majorant(ray, wl);
  // Distances along the ray in units of its parameter t.
  const float speed = length(ray.d);
  Spectrum tMaj(1.0f);  // since the last collision
  int collisions = 0, stalled = 0;
  while (const std::optional<MajorantSegment> segment = segments.next()) {
    const Spectrum& sigmaMaj = segment->sigmaMaj;
    float t = segment->tmin;
    while (true) {
      const float step = sigmaMaj[0] > 0.0f ? -std::log(1.0f - rng.nextFloat()) / (sigmaMaj[0] * speed) : INFINITY;
      if (!(t + step < segment->tmax)) {
        tMaj *= majorantTransmittance(sigmaMaj, (segment->tmax - t) * speed);
        break;
      }
      stalled = t + step == t ? stalled + 1 : 0;
      if (++collisions > kMostTentativeCollisions || stalled > kMostStalledCollisions) {
        medium.warnWalkCut(collisions - 1);
        return Spectrum(0.0f);
      }
      t += step;
      const Vec3 p = ray.at(t);
      if (!visit(p, medium.coefficients(p, wl), sigmaMaj, tMaj * majorantTransmittance(sigmaMaj, step * speed)))
        return Spectrum(1.0f);
      tMaj = Spectrum(1.0f);
    }
  }
  return tMaj;
}

}  // namespace columba
