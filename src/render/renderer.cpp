#include "render/renderer.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
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
// The camera ray of a sample of pixel (x, y): an offset drawn from the filter, then a point on
// the lens, drawn only for sensors that have one, so pinhole sensors' samples stay as they were.
std::optional<Ray> cameraRay(const Sensor& sensor, int x, int y, Sampler& sampler) {
  const Vec2 offset = sensor.film().filter().sample(sampler.get2D());
  const Vec2 aperture = sensor.needsApertureSample() ? sampler.get2D() : Vec2(0.5f, 0.5f);
  return sensor.generateRay(Vec2(x + 0.5f + offset.x, y + 0.5f + offset.y), aperture);
}
}  // namespace

Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const Integrator& integrator = scene.integrator();
  const bool whole = settings.window.empty();
  const PixelRect window = whole ? film.crop() : settings.window;
  if (window.x0 < 0 || window.y0 < 0 || window.x1 > film.width() || window.y1 > film.height())
    throw std::runtime_error(fmt::format("the window [{}, {}) x [{}, {}) is not inside the film of {} x {} pixels",
                                         window.x0, window.x1, window.y0, window.y1, film.width(), film.height()));
  const int width = window.width(), height = window.height();
  const int spp = settings.samplesPerPixel > 0 ? settings.samplesPerPixel : sensor.sampler().sampleCount();
  const int sampleBegin = settings.sampleBegin, sampleEnd = settings.sampleEnd > 0 ? settings.sampleEnd : spp;
  if (sampleBegin < 0 || sampleBegin >= sampleEnd || sampleEnd > spp)
    throw std::runtime_error(fmt::format("the sample indices [{}, {}) are not a range within the {} samples per pixel",
                                         sampleBegin, sampleEnd, spp));
  const int count = sampleEnd - sampleBegin;  // samples per pixel of this piece
  const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
  const int tileCount = tilesX * tilesY;

  const float reach = film.filter().radius();  // of a camera sample from its pixel's centre
  Image image = whole ? film.makeImage() : film.resized(width, height)->makeImage();
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
      // (x0, y0): the tile's corner in the image; (x, y): a pixel of the film.
      const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
      for (int y = window.y0 + y0; y < window.y0 + std::min(y0 + kTileSize, height); ++y)
        for (int x = window.x0 + x0; x < window.x0 + std::min(x0 + kTileSize, width); ++x) {
          if (stopRequested()) return;
          double sum[3] = {0, 0, 0};
          std::fill(binSums.begin(), binSums.end(), 0.0);
          const bool seen =
              sensor.seesAnyOf(Vec2(x + 0.5f - reach, y + 0.5f - reach), Vec2(x + 0.5f + reach, y + 0.5f + reach));
          for (int s = sampleBegin; seen && s < sampleEnd; ++s) {
            if (stopRequested()) return;  // the unfinished pixel stays black
            sampler->startPixelSample(x, y, s, settings.seed);
            Wavelengths wl = Wavelengths::sampleVisible(sampler->get1D());
            std::optional<Ray> ray = cameraRay(sensor, x, y, *sampler);
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
          const int ix = x - window.x0, iy = y - window.y0;
          float* p = image.pixel(ix, iy);
          for (int c = 0; c < 3; ++c) p[c] = float(sum[c] / count);
          for (int b = 0; b < bins.count; ++b)
            image.spectral.values[(size_t(iy) * width + ix) * bins.count + b] = float(binSums[b] / count);
        }
      rays += tileRays;
      nonFinite += tileNonFinite;
      samples +=
          uint64_t(count) * uint64_t(std::min(kTileSize, width - x0)) * uint64_t(std::min(kTileSize, height - y0));
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

std::vector<uint64_t> estimateRowCosts(const Scene& scene, const RenderSettings& settings) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const Integrator& integrator = scene.integrator();
  const int width = film.width(), height = film.height();
  // Every stride-th pixel of every stride-th row, at most about 16,384 pixels.
  const int stride = std::max(1, int(std::ceil(std::sqrt(double(width) * double(height) / 16384.0))));
  const int sampledRows = (height + stride - 1) / stride;
  const float reach = film.filter().radius();
  std::vector<uint64_t> blockCosts(size_t(sampledRows), 0);
  std::unique_ptr<tbb::global_control> threadLimit;
  if (settings.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, settings.threads);
  tbb::parallel_for(tbb::blocked_range<int>(0, sampledRows, 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = sensor.sampler().clone();
    for (int block = range.begin(); block != range.end(); ++block) {
      const int y = std::min(block * stride + stride / 2, height - 1);
      uint64_t cost = 0;
      for (int x = std::min(stride / 2, width - 1); x < width; x += stride) {
        if (!sensor.seesAnyOf(Vec2(x + 0.5f - reach, y + 0.5f - reach), Vec2(x + 0.5f + reach, y + 0.5f + reach))) {
          cost += 1;  // an unseen pixel costs next to nothing
          continue;
        }
        uint64_t rays = 0;
        sampler->startPixelSample(x, y, 0, settings.seed);
        Wavelengths wl = Wavelengths::sampleVisible(sampler->get1D());
        if (std::optional<Ray> ray = cameraRay(sensor, x, y, *sampler))
          integrator.radiance(scene, *ray, *sampler, wl, rays);
        cost += 20 * (rays + 2);  // the rays, and the camera sample's own work as two more
      }
      blockCosts[size_t(block)] = cost;
    }
  });
  std::vector<uint64_t> rowCosts(static_cast<size_t>(height));
  for (int y = 0; y < height; ++y) rowCosts[size_t(y)] = blockCosts[size_t(std::min(y / stride, sampledRows - 1))];
  return rowCosts;
}

}  // namespace columba
