#pragma once
// Renders a scene's image: tiles in parallel (oneTBB), every pixel's samples drawn from a
// sampler seeded by (pixel, sample index, seed) only, so the image is bit-identical for any
// thread count.
#include <atomic>
#include <functional>
#include "io/image.h"
#include "scene/scene.h"

namespace columba {

struct RenderSettings {
  int samplesPerPixel = 0;  // 0: the scene sampler's sample_count
  uint64_t seed = 0;
  int threads = 0;          // 0: all hardware threads
  const std::atomic<bool>* cancel = nullptr;  // set to stop early (checked before every sample); finished tiles are kept
  // Radiance per wavelength bin besides RGB (Image::spectral): `spectralBins` equal bins over
  // [spectralMin, spectralMax] nm, each pixel's mean of the bin's mean radiance. 0: RGB only.
  int spectralBins = 0;
  float spectralMin = 400.0f, spectralMax = 700.0f;
  // Called from worker threads as tiles finish (done, total); must be thread-safe.
  std::function<void(int, int)> onTileDone;
};

struct RenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;
  uint64_t rays = 0;
  uint64_t nonFiniteSamples = 0;  // radiance estimates with a NaN or infinity, left out of their pixels
  bool complete = true;  // false when cancelled
};

Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats);

}  // namespace columba
