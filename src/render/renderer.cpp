#include "render/renderer.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

#include "integrators/integrator.h"

namespace columba {

namespace {
constexpr int kTileSize = 16;

// Bins of equal width over a wavelength range, for spectral output.
struct WavelengthBins {
  int count = 0;
  float lo = 0.0f, width = 1.0f;

  // Adds one camera sample's estimate of every bin's mean radiance to `sums`: each of the path's
  // wavelengths has the visible density as its marginal, so L / (pdf * bin width), averaged over
  // the wavelengths, estimates the bin's integral of L divided by its width.
  void accumulate(const Spectrum& L, const Wavelengths& wl, double* sums) const {
    for (int k = 0; k < kSpectrumSamples; ++k) {
      int bin = int(std::floor((wl[k] - lo) / width));
      if (bin < 0 || bin >= count || !(wl.pdf[k] > 0.0f)) continue;
      sums[bin] += double(L[k]) / (double(wl.pdf[k]) * width * kSpectrumSamples);
    }
  }
};
}  // namespace

Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const Integrator& integrator = scene.integrator();
  const int width = film.width(), height = film.height();
  const int spp = settings.samplesPerPixel > 0 ? settings.samplesPerPixel : sensor.sampler().sampleCount();
  const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
  const int tileCount = tilesX * tilesY;

  const float reach = film.filter().radius();  // of a camera sample from its pixel's centre
  Image image = film.makeImage();
  WavelengthBins bins;
  if (settings.spectralBins > 0) {
    bins = {settings.spectralBins, settings.spectralMin,
            (settings.spectralMax - settings.spectralMin) / float(settings.spectralBins)};
    for (int b = 0; b < bins.count; ++b) image.spectral.centres.push_back(bins.lo + (b + 0.5f) * bins.width);
    image.spectral.values.assign(size_t(width) * size_t(height) * size_t(bins.count), 0.0f);
  }
  std::atomic<uint64_t> rays{0}, samples{0};
  std::atomic<int> tilesDone{0};
  std::atomic<bool> cancelled{false};
  std::unique_ptr<tbb::global_control> threadLimit;
  if (settings.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, settings.threads);

  auto start = std::chrono::steady_clock::now();
  std::atomic<uint64_t> nonFinite{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tileCount, 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = sensor.sampler().clone();
    std::vector<double> binSums(size_t(bins.count));
    // Checked before every sample, so that a stop request is answered within one sample at any
    // sample count (a relaxed load of a flag that is rarely written costs next to nothing).
    auto stopRequested = [&] {
      if (!settings.cancel || !settings.cancel->load(std::memory_order_relaxed)) return false;
      cancelled = true;
      return true;
    };
    for (int tile = range.begin(); tile != range.end(); ++tile) {
      uint64_t tileRays = 0, tileNonFinite = 0;
      const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
      for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
        for (int x = x0; x < std::min(x0 + kTileSize, width); ++x) {
          if (stopRequested()) return;
          double sum[3] = {0, 0, 0};
          std::fill(binSums.begin(), binSums.end(), 0.0);
          const bool seen = sensor.seesAnyOf(Vec2(x + 0.5f - reach, y + 0.5f - reach), Vec2(x + 0.5f + reach, y + 0.5f + reach));
          for (int s = 0; seen && s < spp; ++s) {
            if (stopRequested()) return;  // the unfinished pixel stays black
            sampler->startPixelSample(x, y, s, settings.seed);
            Wavelengths wl = Wavelengths::sampleVisible(sampler->get1D());
            Vec2 offset = film.filter().sample(sampler->get2D());
            std::optional<Ray> ray = sensor.generateRay(Vec2(x + 0.5f + offset.x, y + 0.5f + offset.y));
            if (!ray) continue;
            Spectrum L = integrator.radiance(scene, *ray, *sampler, wl, tileRays);
            if (!L.isFinite()) {  // a numerical failure must not poison the pixel; it is counted
              ++tileNonFinite;
              continue;
            }
            if (bins.count > 0) bins.accumulate(L, wl, binSums.data());
            Vec3 rgb = spectrumToRGB(L, wl);
            sum[0] += rgb.x;
            sum[1] += rgb.y;
            sum[2] += rgb.z;
          }
          float* p = image.pixel(x, y);
          for (int c = 0; c < 3; ++c) p[c] = float(sum[c] / spp);
          for (int b = 0; b < bins.count; ++b)
            image.spectral.values[(size_t(y) * width + x) * bins.count + b] = float(binSums[b] / spp);
        }
      rays += tileRays;
      nonFinite += tileNonFinite;
      samples += uint64_t(spp) * uint64_t(std::min(kTileSize, width - x0)) * uint64_t(std::min(kTileSize, height - y0));
      int done = ++tilesDone;
      if (settings.onTileDone) settings.onTileDone(done, tileCount);
    }
  });
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.rays = rays;
  stats.samples = samples;
  stats.nonFiniteSamples = nonFinite;
  stats.complete = !cancelled && tilesDone == tileCount;
  return image;
}

}  // namespace columba
