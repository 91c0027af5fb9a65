#include "render/light_path_renderer.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <vector>

#include "render/splat_buffer.h"
#include "render/thread_limit.h"

namespace columba {

namespace {
// At least this many samples per block, and at least a quarter of the window's pixels: summing a
// block costs a pass over its buffer, small next to its paths.
constexpr uint64_t kMinSamplesPerBlock = 4096;
// Block buffers in memory at once: as many as fit in this budget, at most kMaxBuffers.
constexpr size_t kBufferBudgetBytes = size_t(256) << 20;
constexpr size_t kMaxBuffers = 32;

void refuseUnsupportedSettings(const RenderSettings& settings, const Film& film, int spp) {
  auto refuse = [](const char* what) {
    throw std::runtime_error(fmt::format("ptracer renders whole images: {} cannot be used with light tracing", what));
  };
  if (!settings.window.empty()) refuse("a window of the film (a part of a split render)");
  if (settings.sampleBegin != 0 || (settings.sampleEnd != 0 && settings.sampleEnd != spp))
    refuse("a range of sample indices (a pass of a split render)");
  if (settings.adaptive) refuse("adaptive sampling");
  if (settings.spectralBins > 0) refuse("spectral output");
  if (film.observer()) refuse("a film with a bird's observer (cone catches)");
}

// Turns a light sample's splats into RGB in a block's buffer, leaving out (and counting)
// non-finite values.
class BlockSplats : public FilmSplats {
 public:
  BlockSplats(SplatBuffer& buffer, uint64_t& nonFinite) : buffer_(buffer), nonFinite_(nonFinite) {}
  void setWavelengths(const Wavelengths& wl) { wl_ = wl; }
  void add(Vec2 filmPosition, const Spectrum& value) override {
    if (!value.isFinite()) {
      ++nonFinite_;
      return;
    }
    buffer_.add(filmPosition, spectrumToRGB(value, wl_));
  }

 private:
  SplatBuffer& buffer_;
  uint64_t& nonFinite_;
  Wavelengths wl_;
};
}  // namespace

Image renderLightPaths(const Scene& scene, const ParticleTracerIntegrator& tracer, const RenderSettings& settings,
                       RenderStats& stats) {
  const Sensor& sensor = scene.sensor();
  const Film& film = sensor.film();
  const int spp = settings.samplesPerPixel > 0 ? settings.samplesPerPixel : sensor.sampler().sampleCount();
  refuseUnsupportedSettings(settings, film, spp);
  const PixelRect window = film.crop();
  const uint64_t pixels = uint64_t(window.width()) * uint64_t(window.height());
  const uint64_t total = pixels * uint64_t(spp);
  const uint64_t perBlock = std::max(kMinSamplesPerBlock, (pixels + 3) / 4);
  const uint64_t blocks = (total + perBlock - 1) / perBlock;
  const size_t bufferBytes = size_t(pixels) * 3 * sizeof(double);
  const size_t buffers =
      std::min<size_t>({std::max<size_t>(1, kBufferBudgetBytes / bufferBytes), kMaxBuffers, size_t(blocks)});

  const auto threadLimit = limitThreads(settings.threads);
  const FilterFootprint footprint(film.filter());
  std::vector<SplatBuffer> blockBuffers(buffers, SplatBuffer(window, footprint));
  std::vector<double> sums(size_t(pixels) * 3, 0.0);
  std::atomic<uint64_t> rays{0}, nonFinite{0};
  std::atomic<int> blocksDone{0};
  std::atomic<bool> cancelled{false};
  uint64_t samplesDone = 0;
  auto start = std::chrono::steady_clock::now();

  for (uint64_t first = 0; first < blocks && !cancelled; first += buffers) {
    const size_t count = size_t(std::min<uint64_t>(buffers, blocks - first));
    std::vector<char> finished(count, 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 1), [&](const tbb::blocked_range<size_t>& range) {
      std::unique_ptr<Sampler> sampler = sensor.sampler().withSampleCount(spp);
      for (size_t b = range.begin(); b != range.end(); ++b) {
        SplatBuffer& buffer = blockBuffers[b];
        buffer.clear();
        uint64_t blockRays = 0, blockNonFinite = 0;
        BlockSplats splats(buffer, blockNonFinite);
        const uint64_t begin = (first + b) * perBlock, end = std::min(total, begin + perBlock);
        bool stopped = false;
        for (uint64_t k = begin; k < end; ++k) {
          if (settings.cancel && settings.cancel->load(std::memory_order_relaxed)) {
            cancelled = true;
            stopped = true;
            break;
          }
          // The sample's place among the window's pixels only names it for the sampler. Consecutive
          // samples take one pixel's sample indices in turn, as camera paths do, so that samplers
          // that lay out a pixel's whole pattern at once (ldsampler) do it once per pixel.
          const uint64_t pixel = k / uint64_t(spp);
          sampler->startPixelSample(window.x0 + int(pixel % uint64_t(window.width())),
                                    window.y0 + int(pixel / uint64_t(window.width())), int(k % uint64_t(spp)),
                                    settings.seed);
          const Wavelengths wl = Wavelengths::sample(sampler->get1D(), WavelengthDensity::RGBMatching);  // RGB only
          splats.setWavelengths(wl);
          tracer.trace(scene, *sampler, wl, splats, blockRays);
        }
        rays += blockRays;
        nonFinite += blockNonFinite;
        if (stopped) return;  // an unfinished block is left out
        finished[b] = 1;
        int done = ++blocksDone;
        if (settings.onTileDone) settings.onTileDone(done, int(blocks));
      }
    });
    // Each pixel sums the round's blocks in block order: the same additions for any threads.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, sums.size()), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t b = 0; b < count; ++b) {
        if (!finished[b]) continue;
        const std::vector<double>& block = blockBuffers[b].sums();
        for (size_t i = range.begin(); i != range.end(); ++i) sums[i] += block[i];
      }
    });
    for (size_t b = 0; b < count; ++b)
      if (finished[b]) samplesDone += std::min(total, (first + b + 1) * perBlock) - (first + b) * perBlock;
  }

  // Each sample's importance spreads over the whole film: the film's pixel count over the
  // samples, and each pixel's filter mass on the film (as a camera sample's splats are divided),
  // make each pixel what camera samples estimate.
  Image image = film.makeImage();
  const double scale = samplesDone > 0 ? double(film.width()) * double(film.height()) / double(samplesDone) : 0.0;
  for (int y = 0; y < window.height(); ++y)
    for (int x = 0; x < window.width(); ++x) {
      float* p = image.pixel(x, y);
      const size_t i = (size_t(y) * size_t(window.width()) + size_t(x)) * 3;
      const double mass =
          footprint.massWithin(window.x0 + x, film.width()) * footprint.massWithin(window.y0 + y, film.height());
      for (int c = 0; c < 3; ++c) p[c] = float(sums[i + size_t(c)] * scale / mass);
    }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stats.rays = rays;
  stats.samples = samplesDone;
  stats.nonFiniteSamples = nonFinite;
  stats.complete = !cancelled;
  return image;
}

}  // namespace columba
