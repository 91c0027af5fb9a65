#include "render/renderer.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "integrators/integrator.h"
#include "render/light_path_renderer.h"
#include "render/sample_allocation.h"
#include "render/thread_limit.h"
#include "samplers/sampler_parameters.h"

namespace columba {

namespace {
constexpr int kTileSize = 16;

// Bins of equal width over a wavelength range, for spectral output.
struct WavelengthBins {
  int count = 0;
  float lo = 0.0f, width = 1.0f;

  // Adds one camera sample's estimate of every bin's mean radiance to `sums`: each of the path's
  // wavelengths has the sampling density as its marginal, so L / (pdf * bin width), averaged over
  // the wavelengths, estimates the bin's integral of L divided by its width.
  void accumulate(const Spectrum& L, const Wavelengths& wl, double* sums) const {
    for (int k = 0; k < kSpectrumSamples; ++k) {
      int bin = int(std::floor((wl[k] - lo) / width));
      if (bin < 0 || bin >= count || !(wl.pdf[k] > 0.0f)) continue;
      sums[bin] += double(L[k]) / (double(wl.pdf[k]) * width * kSpectrumSamples);
    }
  }
};

// Wavelengths follow what the image records: the RGB matching functions, or, where spectral bins
// are written too, the visible density, which keeps more of the range's ends for the outer bins.
WavelengthDensity wavelengthDensity(const RenderSettings& settings) {
  return settings.spectralBins > 0 ? WavelengthDensity::Visible : WavelengthDensity::RGBMatching;
}

// The camera ray of a sample of pixel (x, y): an offset drawn from the filter, then a point on
// the lens, drawn only for sensors that have one (`lens`: sensor.needsApertureSample(), asked
// once per render), so pinhole sensors' samples stay as they were.
std::optional<Ray> cameraRay(const Sensor& sensor, bool lens, int x, int y, Sampler& sampler) {
  const Vec2 offset = sensor.film().filter().sample(sampler.get2D());
  const Vec2 aperture = lens ? sampler.get2D() : Vec2(0.5f, 0.5f);
  return sensor.generateRay(Vec2(x + 0.5f + offset.x, y + 0.5f + offset.y), aperture);
}

// What a pixel's samples add up to: RGB, and the luminance and its square for adaptive sampling.
struct PixelSums {
  double rgb[3] = {0, 0, 0};
  double luminance = 0.0, luminanceSquares = 0.0;
  int taken = 0;  // sample indices drawn (those without a ray or with a non-finite value count too)
};

// Draws the samples of single pixels, for both kinds of render.
struct PixelSampler {
  const Scene& scene;
  const Sensor& sensor;
  const Integrator& integrator;
  const WavelengthBins& bins;
  WavelengthDensity wavelengths;
  uint64_t seed;
  float reach;  // of a camera sample from its pixel's centre
  bool lens;    // the sensor draws an aperture sample

  bool sees(int x, int y) const {
    return sensor.seesAnyOf(Vec2(x + 0.5f - reach, y + 0.5f - reach), Vec2(x + 0.5f + reach, y + 0.5f + reach));
  }
  // Adds samples [begin, end) of pixel (x, y) to `sums` and `binSums`; false when `stop()` asked to
  // stop first (checked before every sample).
  template <typename Stop>
  bool add(Sampler& sampler, int x, int y, int begin, int end, PixelSums& sums, double* binSums, uint64_t& rays,
           uint64_t& nonFinite, const Stop& stop) const {
    for (int s = begin; s < end; ++s) {
      if (stop()) return false;
      ++sums.taken;
      sampler.startPixelSample(x, y, s, seed);
      Wavelengths wl = Wavelengths::sample(sampler.get1D(), wavelengths);
      std::optional<Ray> ray = cameraRay(sensor, lens, x, y, sampler);
      if (!ray) continue;
      Spectrum L = integrator.radiance(scene, *ray, sampler, wl, rays);
      if (!L.isFinite()) {  // a numerical failure must not poison the pixel; it is counted
        ++nonFinite;
        continue;
      }
      if (bins.count > 0) bins.accumulate(L, wl, binSums);
      Vec3 rgb = spectrumToRGB(L, wl);
      sums.rgb[0] += rgb.x;
      sums.rgb[1] += rgb.y;
      sums.rgb[2] += rgb.z;
      double luminance = 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
      sums.luminance += luminance;
      sums.luminanceSquares += luminance * luminance;
    }
    return true;
  }
};

// The tiles of a window, rendered in parallel; `pixel(sampler, scratch, x, y, stop)` renders one
// pixel (film coordinates) and returns false once a stop was requested. `scratch` holds
// `scratchSize` doubles for the pixel to use, allocated once per group of tiles.
template <typename RenderPixel>
void forEachTile(const PixelRect& window, const RenderSettings& settings, const Sampler& prototype, size_t scratchSize,
                 int progressBase, int progressTotal, std::atomic<bool>& cancelled, const RenderPixel& pixel) {
  const int width = window.width(), height = window.height();
  const int tilesX = (width + kTileSize - 1) / kTileSize, tilesY = (height + kTileSize - 1) / kTileSize;
  std::atomic<int> tilesDone{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = prototype.clone();
    std::vector<double> scratch(scratchSize);
    // Checked before every sample, so that a stop request is answered within one sample at any
    // sample count (a relaxed load of a flag that is rarely written costs next to nothing).
    auto stopRequested = [&] {
      if (!settings.cancel || !settings.cancel->load(std::memory_order_relaxed)) return false;
      cancelled = true;
      return true;
    };
    for (int tile = range.begin(); tile != range.end(); ++tile) {
      // (x0, y0): the tile's corner in the window; (x, y): a pixel of the film.
      const int x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
      for (int y = window.y0 + y0; y < window.y0 + std::min(y0 + kTileSize, height); ++y)
        for (int x = window.x0 + x0; x < window.x0 + std::min(x0 + kTileSize, width); ++x)
          if (!pixel(*sampler, scratch, x, y, stopRequested)) return;
      int done = ++tilesDone;
      if (settings.onTileDone) settings.onTileDone(progressBase + done, progressTotal);
    }
  });
}

// A quarter of the budget, 2 to 16, rounded down to a power of two: the progressive pattern's
// prefixes of that size are stratified.
int pilotSamplesFor(int spp) {
  int pilot = 2;
  while (pilot * 2 <= std::min(spp / 4, 16)) pilot *= 2;
  return pilot;
}

}  // namespace

Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats) {
  if (const ParticleTracerIntegrator* tracer = scene.particleTracer())
    return renderLightPaths(scene, *tracer, settings, stats);
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
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
  if (settings.adaptive && (!whole || sampleBegin != 0 || sampleEnd != spp))
    throw std::runtime_error("adaptive sampling renders whole images: it cannot be split into parts or passes");
  if (settings.adaptive && spp < 4)
    throw std::runtime_error(fmt::format("adaptive sampling needs 4 or more samples per pixel, not {}", spp));

  Image image = whole ? film.makeImage() : film.resized(width, height)->makeImage();
  WavelengthBins bins;
  if (settings.spectralBins > 0) {
    bins = {settings.spectralBins, settings.spectralMin,
            (settings.spectralMax - settings.spectralMin) / float(settings.spectralBins)};
    for (int b = 0; b < bins.count; ++b) image.spectral.centres.push_back(bins.lo + (b + 0.5f) * bins.width);
    image.spectral.values.assign(size_t(width) * size_t(height) * size_t(bins.count), 0.0f);
  }
  const auto threadLimit = limitThreads(settings.threads);
  // The scene's sampler with a pattern of this render's sample count.
  const std::unique_ptr<Sampler> pattern = sensor.sampler().withSampleCount(spp);
  const PixelSampler pixels{scene,
                            sensor,
                            scene.integrator(),
                            bins,
                            wavelengthDensity(settings),
                            settings.seed,
                            film.filter().radius(),
                            sensor.needsApertureSample()};
  const int tileCount = ((width + kTileSize - 1) / kTileSize) * ((height + kTileSize - 1) / kTileSize);
  std::atomic<uint64_t> rays{0}, nonFinite{0}, samples{0};
  std::atomic<bool> cancelled{false};
  // Each pixel's value: its sums over its samples.
  auto store = [&](int ix, int iy, const PixelSums& sums, const double* binSums, int count) {
    float* p = image.pixel(ix, iy);
    for (int c = 0; c < 3; ++c) p[c] = count > 0 ? float(sums.rgb[c] / count) : 0.0f;
    for (int b = 0; b < bins.count; ++b)
      image.spectral.values[(size_t(iy) * width + ix) * bins.count + b] = count > 0 ? float(binSums[b] / count) : 0.0f;
  };
  auto start = std::chrono::steady_clock::now();

  if (!settings.adaptive) {
    // Every pixel gets the samples [sampleBegin, sampleEnd).
    const int count = sampleEnd - sampleBegin;
    forEachTile(window, settings, *pattern, size_t(bins.count), 0, tileCount, cancelled,
                [&](Sampler& sampler, std::vector<double>& binSums, int x, int y, const auto& stop) {
                  PixelSums sums;
                  std::fill(binSums.begin(), binSums.end(), 0.0);
                  uint64_t pixelRays = 0, pixelNonFinite = 0;
                  bool finished = !pixels.sees(x, y) || pixels.add(sampler, x, y, sampleBegin, sampleEnd, sums,
                                                                   binSums.data(), pixelRays, pixelNonFinite, stop);
                  rays += pixelRays;
                  nonFinite += pixelNonFinite;
                  if (!finished) return false;  // the unfinished pixel stays black
                  samples += uint64_t(count);
                  store(x - window.x0, y - window.y0, sums, binSums.data(), count);
                  return true;
                });
  } else {
    // A pilot for every pixel, the plan, then the rest of each pixel's samples, from a pattern
    // whose every power-of-two prefix is stratified: with ldsampler's padded pattern the pilot and
    // the rest were random subsets of it, and simulation3's variance per sample 41 % (64 spp) and
    // 87 % (256 spp) above a uniform render's.
    const std::unique_ptr<Sampler> progressive = pattern->withProgressivePattern();
    const int pilot = pilotSamplesFor(spp);
    const size_t pixelCount = size_t(width) * size_t(height);
    std::vector<PixelSums> sums(pixelCount);
    std::vector<double> binSums(pixelCount * size_t(bins.count), 0.0);
    std::vector<PilotPixel> pilotPixels(pixelCount);
    // A film pixel's place in the window's arrays.
    auto windowIndex = [&](int x, int y) { return size_t(y - window.y0) * width + size_t(x - window.x0); };
    auto addRange = [&](Sampler& sampler, int x, int y, int begin, int end, const auto& stop) {
      size_t i = windowIndex(x, y);
      uint64_t pixelRays = 0, pixelNonFinite = 0;
      bool finished = pixels.add(sampler, x, y, begin, end, sums[i], binSums.data() + i * bins.count, pixelRays,
                                 pixelNonFinite, stop);
      rays += pixelRays;
      nonFinite += pixelNonFinite;
      return finished;
    };
    forEachTile(window, settings, *progressive, 0, 0, 2 * tileCount, cancelled,
                [&](Sampler& sampler, std::vector<double>&, int x, int y, const auto& stop) {
                  size_t i = windowIndex(x, y);
                  pilotPixels[i].seen = pixels.sees(x, y);
                  return !pilotPixels[i].seen || addRange(sampler, x, y, 0, pilot, stop);
                });
    SamplePlan plan;
    if (!cancelled) {
      for (size_t i = 0; i < pixelCount; ++i) {
        pilotPixels[i].sum = sums[i].luminance;
        pilotPixels[i].sumSquares = sums[i].luminanceSquares;
      }
      plan = planSamples(pilotPixels, width, height, {pilot, double(spp), settings.targetError, kMaxSamplesPerPixel});
      forEachTile(window, settings, *progressive, 0, tileCount, 2 * tileCount, cancelled,
                  [&](Sampler& sampler, std::vector<double>&, int x, int y, const auto& stop) {
                    size_t i = windowIndex(x, y);
                    return plan.counts[i] <= pilot || addRange(sampler, x, y, pilot, plan.counts[i], stop);
                  });
      stats.pilotSamples = pilot;
      stats.predictedRelativeError = plan.predictedRelativeError;
      bool any = false;
      for (size_t i = 0; i < pixelCount; ++i) {
        if (!pilotPixels[i].seen) continue;
        stats.fewestSamples = any ? std::min(stats.fewestSamples, plan.counts[i]) : plan.counts[i];
        stats.mostSamples = any ? std::max(stats.mostSamples, plan.counts[i]) : plan.counts[i];
        any = true;
      }
    }
    // Each pixel is the mean of the samples it took (all of its plan's unless stopped early).
    for (int iy = 0; iy < height; ++iy)
      for (int ix = 0; ix < width; ++ix) {
        size_t i = size_t(iy) * width + ix;
        samples += uint64_t(sums[i].taken);
        store(ix, iy, sums[i], binSums.data() + i * bins.count, sums[i].taken);
      }
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.rays = rays;
  stats.samples = samples;
  stats.nonFiniteSamples = nonFinite;
  stats.complete = !cancelled;
  return image;
}

std::vector<uint64_t> estimateRowCosts(const Scene& scene, const RenderSettings& settings) {
  if (scene.particleTracer())
    throw std::runtime_error("ptracer renders whole images: its light reaches any row, so it cannot be split by rows");
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const Integrator& integrator = scene.integrator();
  const int width = film.width(), height = film.height();
  // Every stride-th pixel of every stride-th row, at most about 16,384 pixels.
  const int stride = std::max(1, int(std::ceil(std::sqrt(double(width) * double(height) / 16384.0))));
  const int sampledRows = (height + stride - 1) / stride;
  const float reach = film.filter().radius();
  const bool lens = sensor.needsApertureSample();
  std::vector<uint64_t> blockCosts(size_t(sampledRows), 0);
  const auto threadLimit = limitThreads(settings.threads);
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
        Wavelengths wl = Wavelengths::sample(sampler->get1D(), wavelengthDensity(settings));
        if (std::optional<Ray> ray = cameraRay(sensor, lens, x, y, *sampler))
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
