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
#include "render/tiled_splats.h"
#include "samplers/sampler_parameters.h"

namespace columba {

namespace {

// Bins of equal width over a wavelength range, for spectral output.
struct WavelengthBins {
  int count = 0;
  float lo = 0.0f, width = 1.0f;

  // Adds one camera sample's estimate of every bin's mean radiance, times `scale`, to `values`:
  // each of the path's wavelengths has the sampling density as its marginal, so L / (pdf * bin
  // width), averaged over the wavelengths, estimates the bin's integral of L divided by its width.
  void accumulate(const Spectrum& L, const Wavelengths& wl, float scale, float* values) const {
    for (int k = 0; k < kSpectrumSamples; ++k) {
      int bin = int(std::floor((wl[k] - lo) / width));
      if (bin < 0 || bin >= count || !(wl.pdf[k] > 0.0f)) continue;
      values[bin] += float(double(L[k]) * scale / (double(wl.pdf[k]) * width * kSpectrumSamples));
    }
  }
};

// Wavelengths follow what the image records: a bird observer's cones, the RGB matching functions,
// or, where spectral bins are written too, the visible density, which keeps more of the range's
// ends for the outer bins.
const WavelengthTable& wavelengthTable(const RenderSettings& settings, const Film& film) {
  if (const ObserverResponse* observer = film.observer()) return observer->wavelengths();
  return wavelengthTable(settings.spectralBins > 0 ? WavelengthDensity::Visible : WavelengthDensity::RGBMatching);
}

// A camera sample of pixel (x, y): a film position uniform in the pixel, as Mitsuba draws it (the
// filter weighs it for each pixel it reaches), then a point on the lens, drawn only for sensors
// that have one (`lens`: sensor.needsApertureSample(), asked once per render), so pinhole
// sensors' samples stay as they were.
struct CameraSample {
  Vec2 filmPosition;
  std::optional<Ray> ray;
};
CameraSample cameraSample(const Sensor& sensor, bool lens, int x, int y, Sampler& sampler) {
  const Vec2 u = sampler.get2D();
  const Vec2 filmPosition(float(x) + u.x, float(y) + u.y);
  const Vec2 aperture = lens ? sampler.get2D() : Vec2(0.5f, 0.5f);
  return {filmPosition, sensor.generateRay(filmPosition, aperture)};
}

// Draws the samples of single pixels, for both kinds of render.
struct PixelSampler {
  const Scene& scene;
  const Sensor& sensor;
  const Integrator& integrator;
  const WavelengthTable& wavelengths;
  const ObserverResponse* observer;  // null: RGB (and spectral bins) only
  uint64_t seed;
  bool lens;  // the sensor draws an aperture sample

  bool sees(int x, int y) const { return sensor.seesAnyOf(Vec2(float(x), float(y)), Vec2(x + 1.0f, y + 1.0f)); }
  // Draws samples [begin, end) of pixel (x, y), handing each with a finite value to
  // `take(filmPosition, L, wl)`; returns false when `stop()` asked to stop first (checked before
  // every sample). `taken` counts the sample indices drawn (those without a ray or with a
  // non-finite value too).
  template <typename Take, typename Stop>
  bool draw(Sampler& sampler, int x, int y, int begin, int end, uint64_t& rays, uint64_t& nonFinite, int& taken,
            const Take& take, const Stop& stop) const {
    for (int s = begin; s < end; ++s) {
      if (stop()) return false;
      ++taken;
      sampler.startPixelSample(x, y, s, seed);
      Wavelengths wl = Wavelengths::sample(sampler.get1D(), wavelengths);
      CameraSample sample = cameraSample(sensor, lens, x, y, sampler);
      if (!sample.ray) continue;
      Spectrum L = integrator.radiance(scene, *sample.ray, sampler, wl, rays);
      if (!L.isFinite()) {  // a numerical failure must not poison the pixels; it is counted
        ++nonFinite;
        continue;
      }
      take(sample.filmPosition, L, wl);
    }
    return true;
  }
};

// Whether a stop was requested (it then marks the render cancelled). Checked before every sample,
// so that a stop request is answered within one sample at any sample count (a relaxed load of a
// flag that is rarely written costs next to nothing).
auto stopRequested(const RenderSettings& settings, std::atomic<bool>& cancelled) {
  return [&settings, &cancelled] {
    if (!settings.cancel || !settings.cancel->load(std::memory_order_relaxed)) return false;
    cancelled = true;
    return true;
  };
}

// Renders the tiles' window into `image` (and its spectral bins): every pixel within the
// filter's reach of the window draws its samples [sampleBegin, sampleEnd(x, y)), each splatted
// with weight 1 / their count (render/tiled_splats.h). Returns the sample indices the window's
// own pixels drew (those beyond it are drawn too, and count in the rays).
template <typename SampleEnd>
uint64_t splatCameraSamples(const PixelSampler& pixels, const RenderSettings& settings, TiledSplats& tiles,
                            const WavelengthBins& bins, const Sampler& pattern, int sampleBegin,
                            const SampleEnd& sampleEnd, int progressBase, int progressTotal, Image& image,
                            RenderStats& stats, std::atomic<bool>& cancelled) {
  const PixelRect& window = tiles.window();
  const int cones = pixels.observer ? int(pixels.observer->channels().size()) : 0;
  const int channels = 3 + bins.count + cones;
  std::atomic<uint64_t> rays{0}, nonFinite{0}, samples{0};
  std::atomic<int> tilesDone{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles.tileCount(), 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = pattern.clone();
    std::vector<float> values(static_cast<size_t>(channels));
    const auto stop = stopRequested(settings, cancelled);
    for (int tile = range.begin(); tile != range.end(); ++tile) {
      const PixelRect rect = tiles.tilePixels(tile);
      SplatBuffer& buffer = tiles.buffer(tile);
      uint64_t tileRays = 0, tileNonFinite = 0, tileSamples = 0;
      bool finished = true;
      for (int y = rect.y0; y < rect.y1 && finished; ++y)
        for (int x = rect.x0; x < rect.x1 && finished; ++x) {
          const int end = sampleEnd(x, y);
          const bool inWindow = x >= window.x0 && x < window.x1 && y >= window.y0 && y < window.y1;
          if (end <= sampleBegin) continue;
          if (!pixels.sees(x, y)) {  // its samples would all be black: they count, but add nothing
            if (inWindow) tileSamples += uint64_t(end - sampleBegin);
            continue;
          }
          const float weight = 1.0f / float(end - sampleBegin);
          int taken = 0;
          auto take = [&](Vec2 filmPosition, const Spectrum& L, const Wavelengths& wl) {
            if (L.isZero()) return;  // it would add zeros
            const Vec3 rgb = spectrumToRGB(L, wl) * weight;
            values[0] = rgb.x;
            values[1] = rgb.y;
            values[2] = rgb.z;
            if (bins.count > 0) {
              std::fill(values.begin() + 3, values.end(), 0.0f);
              bins.accumulate(L, wl, weight, values.data() + 3);
            }
            if (cones > 0) {
              std::fill(values.begin() + 3 + bins.count, values.end(), 0.0f);
              pixels.observer->accumulate(L, wl, weight, values.data() + 3 + bins.count);
            }
            buffer.add(filmPosition, values.data());
          };
          finished = pixels.draw(*sampler, x, y, sampleBegin, end, tileRays, tileNonFinite, taken, take, stop);
          if (inWindow) tileSamples += uint64_t(taken);
        }
      rays += tileRays;
      nonFinite += tileNonFinite;
      if (!finished) {  // left out, as its pixels' splats are incomplete
        tiles.discard(tile);
        return;
      }
      samples += tileSamples;
      const int done = ++tilesDone;
      if (settings.onTileDone) settings.onTileDone(progressBase + done, progressTotal);
    }
  });

  tiles.resolve([&](int y, const double* values) {
    const int iy = y - window.y0;
    for (int ix = 0; ix < window.width(); ++ix) {
      const double* v = values + size_t(ix) * size_t(channels);
      float* p = image.pixel(ix, iy);
      for (int c = 0; c < 3; ++c) p[c] = float(v[c]);
      for (int b = 0; b < bins.count; ++b)
        image.spectral.values[(size_t(iy) * size_t(window.width()) + size_t(ix)) * size_t(bins.count) + size_t(b)] =
            float(v[3 + b]);
      for (int c = 0; c < cones; ++c)
        image.cones.values[(size_t(iy) * size_t(window.width()) + size_t(ix)) * size_t(cones) + size_t(c)] =
            float(v[3 + bins.count + c]);
    }
  });
  stats.rays += rays;
  stats.nonFiniteSamples += nonFinite;
  return samples;
}

// A quarter of the budget, 2 to 16, rounded down to a power of two: the progressive pattern's
// prefixes of that size are stratified.
int pilotSamplesFor(int spp) {
  int pilot = 2;
  while (pilot * 2 <= std::min(spp / 4, 16)) pilot *= 2;
  return pilot;
}

// The pilot of adaptive sampling over the pixels whose samples reach the window (tiles.sources()),
// tile by tile: each seen pixel's sums of its first `pilot` samples' luminance, row by row.
std::vector<PilotPixel> renderPilot(const PixelSampler& pixels, const RenderSettings& settings, const Sampler& pattern,
                                    const TiledSplats& tiles, int pilot, int progressTotal, RenderStats& stats,
                                    std::atomic<bool>& cancelled) {
  const PixelRect& sources = tiles.sources();
  std::vector<PilotPixel> pilotPixels(size_t(sources.width()) * size_t(sources.height()));
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  std::atomic<int> tilesDone{0};
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles.tileCount(), 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = pattern.clone();
    const auto stop = stopRequested(settings, cancelled);
    for (int tile = range.begin(); tile != range.end(); ++tile) {
      const PixelRect rect = tiles.tilePixels(tile);
      uint64_t tileRays = 0, tileNonFinite = 0;
      for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x) {
          PilotPixel& p = pilotPixels[size_t(y - sources.y0) * size_t(sources.width()) + size_t(x - sources.x0)];
          p.seen = pixels.sees(x, y);
          if (!p.seen) continue;
          int taken = 0;
          auto take = [&](Vec2, const Spectrum& L, const Wavelengths& wl) {
            const Vec3 rgb = spectrumToRGB(L, wl);
            const double luminance = 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;
            p.sum += luminance;
            p.sumSquares += luminance * luminance;
          };
          if (!pixels.draw(*sampler, x, y, 0, pilot, tileRays, tileNonFinite, taken, take, stop)) return;
        }
      rays += tileRays;
      nonFinite += tileNonFinite;
      const int done = ++tilesDone;
      if (settings.onTileDone) settings.onTileDone(done, progressTotal);
    }
  });
  stats.rays += rays;
  stats.nonFiniteSamples += nonFinite;
  return pilotPixels;
}

}  // namespace

void RenderSettings::validate(const RenderSettingNames& names) const {
  auto checkCount = [](const char* name, int value, int highest) {
    if (value < 0 || value > highest)
      throw std::invalid_argument(fmt::format("{} must be between 1 and {}, not {}", name, highest, value));
  };
  checkCount(names.samplesPerPixel, samplesPerPixel, kMaxSamplesPerPixel);
  checkCount(names.threads, threads, kMaxRenderThreads);
  checkCount(names.spectralBins, spectralBins, kMaxSpectralBins);
  if (targetError != 0.0 && !(targetError > 0.0 && targetError < 1.0))
    throw std::invalid_argument(
        fmt::format("{} {}: give the relative RMSE to reach, a number between 0 and 1 (e.g. 0.02)", names.targetError,
                    targetError));
}

std::pair<float, float> spectralRange(const RenderSettings& settings, const Film& film, const std::string& option) {
  const WavelengthTable& rendered = wavelengthTable(settings, film);
  if (settings.spectralMin == 0.0f && settings.spectralMax == 0.0f) return {rendered.first(), rendered.last()};
  const float lo = settings.spectralMin, hi = settings.spectralMax;
  if (!(lo < hi) || !(lo >= rendered.first()) || !(hi <= rendered.last()))
    throw std::invalid_argument(
        fmt::format("{} {:g}-{:g} nm is not a range within the {:g}-{:g} nm this film renders (an RGB film renders "
                    "{:g}-{:g} nm; a film with a bird's observer, its observer's range)",
                    option, lo, hi, rendered.first(), rendered.last(), kLambdaMin, kLambdaMax));
  return {lo, hi};
}

namespace {
Image renderCameraPaths(const Scene& scene, const RenderSettings& settings, RenderStats& stats) {
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
    const auto [lo, hi] = spectralRange(settings, film);
    bins = {settings.spectralBins, lo, (hi - lo) / float(settings.spectralBins)};
    for (int b = 0; b < bins.count; ++b) image.spectral.centres.push_back(bins.lo + (b + 0.5f) * bins.width);
    image.spectral.values.assign(size_t(width) * size_t(height) * size_t(bins.count), 0.0f);
  }
  const auto threadLimit = limitThreads(settings.threads);
  // The scene's sampler with a pattern of this render's sample count.
  const std::unique_ptr<Sampler> pattern = sensor.sampler().withSampleCount(spp);
  const PixelSampler pixels{
      scene,           sensor,        scene.integrator(),          wavelengthTable(settings, film),
      film.observer(), settings.seed, sensor.needsApertureSample()};
  const FilterFootprint footprint(film.filter());
  TiledSplats tiles(window, film.width(), film.height(), footprint, 3 + bins.count + int(image.cones.count()));
  std::atomic<bool> cancelled{false};
  stats.rays = 0;
  stats.nonFiniteSamples = 0;
  auto start = std::chrono::steady_clock::now();

  if (!settings.adaptive) {
    // Every pixel gets the samples [sampleBegin, sampleEnd).
    stats.samples = splatCameraSamples(
        pixels, settings, tiles, bins, *pattern, sampleBegin, [&](int, int) { return sampleEnd; }, 0, tiles.tileCount(),
        image, stats, cancelled);
  } else {
    // A pilot for every pixel gives the plan; then every pixel draws its planned samples, the
    // pilot's again among them (they are the same samples), so that each is splatted with weight
    // 1 / the pixel's count. Both from a pattern whose every power-of-two prefix is stratified:
    // with ldsampler's padded pattern the pilot and the rest would be random subsets of it
    // (docs/performance.md, "Sample patterns and wavelengths").
    const std::unique_ptr<Sampler> progressive = pattern->withProgressivePattern();
    const int pilot = pilotSamplesFor(spp);
    const int progressTotal = 2 * tiles.tileCount();
    const std::vector<PilotPixel> pilotPixels =
        renderPilot(pixels, settings, *progressive, tiles, pilot, progressTotal, stats, cancelled);
    if (!cancelled) {
      const PixelRect& planned = tiles.sources();
      const SamplePlan plan = planSamples(pilotPixels, planned.width(), planned.height(),
                                          {pilot, double(spp), settings.targetError, kMaxSamplesPerPixel});
      auto count = [&](int x, int y) {
        return plan.counts[size_t(y - planned.y0) * size_t(planned.width()) + size_t(x - planned.x0)];
      };
      stats.samples = splatCameraSamples(pixels, settings, tiles, bins, *progressive, 0, count, tiles.tileCount(),
                                         progressTotal, image, stats, cancelled);
      stats.pilotSamples = pilot;
      stats.predictedRelativeError = plan.predictedRelativeError;
      bool any = false;
      for (size_t i = 0; i < pilotPixels.size(); ++i) {
        if (!pilotPixels[i].seen) continue;
        stats.fewestSamples = any ? std::min(stats.fewestSamples, plan.counts[i]) : plan.counts[i];
        stats.mostSamples = any ? std::max(stats.mostSamples, plan.counts[i]) : plan.counts[i];
        any = true;
      }
    }
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.complete = !cancelled;
  return image;
}

// A render whose pixels are not all finite is no image: its values overflowed float (emitted
// values that the estimators' weights carry past 3.4e38) or an estimate failed in a way the
// per-sample check could not see. Throws, naming how many and the first.
void requireFinite(const Image& image) {
  const std::pair<const char*, const std::vector<float>*> parts[] = {
      {"RGB", &image.rgb}, {"spectral band", &image.spectral.values}, {"cone", &image.cones.values}};
  for (const auto& [what, values] : parts) {
    const auto first = std::find_if(values->begin(), values->end(), [](float v) { return !std::isfinite(v); });
    if (first == values->end()) continue;
    const size_t count =
        size_t(std::count_if(values->begin(), values->end(), [](float v) { return !std::isfinite(v); }));
    const size_t perPixel = values->size() / (size_t(image.width) * size_t(image.height));
    const size_t index = size_t(first - values->begin()), pixel = index / perPixel;
    throw std::runtime_error(fmt::format(
        "the render is not finite: {} of its {} {} values are NaN or infinite (the first, {}, at pixel ({}, {}), "
        "channel {}); the scene's light overflows a float image (emitters too bright for their distance, or "
        "textures of huge values): no image was written",
        count, values->size(), what, std::isnan(*first) ? "NaN" : "infinite", pixel % size_t(image.width),
        pixel / size_t(image.width), index % perPixel));
  }
}
}  // namespace

Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats) {
  const ParticleTracerIntegrator* tracer = scene.particleTracer();
  Image image = tracer ? renderLightPaths(scene, *tracer, settings, stats) : renderCameraPaths(scene, settings, stats);
  requireFinite(image);
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
  const bool lens = sensor.needsApertureSample();
  std::vector<uint64_t> blockCosts(size_t(sampledRows), 0);
  const auto threadLimit = limitThreads(settings.threads);
  tbb::parallel_for(tbb::blocked_range<int>(0, sampledRows, 1), [&](const tbb::blocked_range<int>& range) {
    std::unique_ptr<Sampler> sampler = sensor.sampler().clone();
    for (int block = range.begin(); block != range.end(); ++block) {
      const int y = std::min(block * stride + stride / 2, height - 1);
      uint64_t cost = 0;
      for (int x = std::min(stride / 2, width - 1); x < width; x += stride) {
        if (!sensor.seesAnyOf(Vec2(float(x), float(y)), Vec2(x + 1.0f, y + 1.0f))) {
          cost += 1;  // an unseen pixel costs next to nothing
          continue;
        }
        uint64_t rays = 0;
        sampler->startPixelSample(x, y, 0, settings.seed);
        Wavelengths wl = Wavelengths::sample(sampler->get1D(), wavelengthTable(settings, film));
        if (const CameraSample sample = cameraSample(sensor, lens, x, y, *sampler); sample.ray)
          integrator.radiance(scene, *sample.ray, *sampler, wl, rays);
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
