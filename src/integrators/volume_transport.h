#pragma once
// Light transport through participating media with spectral multiple importance sampling: a path
// carries four wavelengths, and collisions are drawn for the hero (lane 0) alone. Besides its
// throughput, a path keeps, per lane, the ratio of the density with which that lane as hero would
// have drawn the path to the density with which it was drawn (rU: by following the path; rL: with
// its last segment drawn by emitter sampling instead). A contribution divided by the mean of those
// ratios over the lanes is the balance heuristic over the four lanes as hero, which keeps lanes
// whose extinction differs from the hero's from becoming noise (Wilkie et al. 2014; Miller,
// Georgiev and Jarosz 2019, as pbrt-v4 and Mitsuba 3's volpathmis do).
#include "core/rng.h"
#include "media/medium.h"
#include "scene/scene.h"

namespace columba {

// A transmittance estimate with its spectral-MIS density ratios (all 1 before the first medium).
struct TrackedTransmittance {
  Spectrum T{1.0f};   // transmittance over the hero's density of drawing what was drawn
  Spectrum rU{1.0f};  // each lane's density as hero of passing by following the path, over the hero's
  Spectrum rL{1.0f};  // each lane's density as hero of passing by ratio tracking, over the hero's
};

// Ratio tracking along `ray` (ray.tmin to ray.tmax) through `medium`: at each tentative collision
// the estimate is weighted by the chance it is null, sigma_n / sigma_maj, with Russian roulette
// once it is small. T / mean(rL) is an unbiased estimate of each lane's transmittance.
void ratioTrack(const Medium& medium, const Ray& ray, const Wavelengths& wl, PCG32& rng, TrackedTransmittance& tr);

// The transmittance along a shadow ray that starts in `medium` (null: none), through the media it
// crosses and the pass-through surfaces (null BSDFs) between them; T = 0 where a surface that does
// not let light through, or an emitter's, is in the way. Counts the rays it traces.
TrackedTransmittance shadowTransmittance(const Scene& scene, Ray ray, const Medium* medium, const Wavelengths& wl,
                                         PCG32& rng, uint64_t& rays);

}  // namespace columba
