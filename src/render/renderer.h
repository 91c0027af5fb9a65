#pragma once
// Renders a scene's image: tiles in parallel (oneTBB), every pixel's samples drawn from a
// sampler seeded by (pixel, sample index, seed) only and splatted over the pixels their filter
// reaches, tile by tile into buffers summed in a fixed order (render/tiled_splats.h), so the image
// is bit-identical for any thread count. A scene whose integrator is `ptracer` is rendered by
// light tracing instead (render/light_path_renderer.h).
#include <atomic>
#include <functional>
#include <string>
#include <utility>
#include <vector>
#include "io/image.h"
#include "scene/scene.h"

namespace columba {

inline constexpr int kMaxRenderThreads = 65536;
inline constexpr int kMaxSpectralBins = 530;  // 1 nm bins over 300-830 nm

// What the settings are called where they were given (the command line's options, Python's
// keyword arguments), for RenderSettings::validate's messages.
struct RenderSettingNames {
  const char* samplesPerPixel;
  const char* threads;
  const char* targetError;
  const char* spectralBins;
};

struct RenderSettings {
  int samplesPerPixel = 0;  // 0: the scene sampler's sample_count
  uint64_t seed = 0;
  int threads = 0;  // 0: all hardware threads
  const std::atomic<bool>* cancel =
      nullptr;  // set to stop early (checked before every sample); finished tiles are kept
  // Radiance per wavelength bin besides RGB (Image::spectral): `spectralBins` equal bins over
  // [spectralMin, spectralMax] nm, each pixel's mean of the bin's mean radiance. 0: RGB only.
  // Both 0: the whole range the film renders (spectralRange); a range must lie within it.
  int spectralBins = 0;
  float spectralMin = 0.0f, spectralMax = 0.0f;
  // Called from worker threads as tiles finish (done, total); must be thread-safe.
  std::function<void(int, int)> onTileDone;
  // A piece of the render. `window` (empty: the film's crop window, normally the whole film)
  // limits it to those pixels of the film, and the image returned holds just them.
  // [sampleBegin, sampleEnd) limits every pixel to those of its sample indices 0 .. spp - 1
  // (sampleEnd 0: spp), and each pixel holds their estimate, linear in them. A pixel's samples
  // depend only on (pixel, sample index, seed), and a window also draws those of the pixels
  // within its filter's reach, so a window of a render is bit for bit the same pixels of the
  // whole render.
  PixelRect window;
  int sampleBegin = 0, sampleEnd = 0;
  // Adaptive sampling (render/sample_allocation.h; whole renders only): samplesPerPixel becomes
  // the mean number of samples per seen pixel. A pilot of a quarter of them (2 to 16) goes to
  // every pixel, the rest where one sample varies most. With targetError > 0, only what the plan
  // predicts for that relative RMSE is spent, at most the budget.
  bool adaptive = false;
  double targetError = 0.0;

  // Throws std::invalid_argument, naming the setting as `names` do, for a sample count, thread
  // count or spectral bin count out of range (0 is allowed for each: the scene's, all cores, RGB
  // only) or a target error outside (0, 1) other than 0 (none).
  void validate(const RenderSettingNames& names) const;
};

struct RenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;  // of the image's own pixels (a window draws those within reach of it too)
  uint64_t rays = 0;
  uint64_t nonFiniteSamples = 0;  // radiance estimates with a NaN or infinity, left out of their pixels
  bool complete = true;           // false when cancelled
  // Adaptive sampling: the pilot's samples per pixel, the fewest and most any seen pixel got, and
  // the relative RMSE the plan predicted.
  int pilotSamples = 0, fewestSamples = 0, mostSamples = 0;
  double predictedRelativeError = 0.0;
};

// The wavelengths the spectral bins cover, [first, last] nm: the settings' range, or where they
// give none the whole range the film renders (360-830 nm for an RGB film, its observer's for a
// film with a bird's observer). Throws std::invalid_argument, naming `option`, for a range that is
// empty or reaches beyond what the film renders (its bins would be empty, not dark).
std::pair<float, float> spectralRange(const RenderSettings& settings, const Film& film,
                                      const std::string& option = "the spectral range");

// Renders the scene's image (or the window of it the settings name). Every value of the image is
// finite: one that is not fails the render with std::runtime_error, naming how many and where.
Image renderImage(const Scene& scene, const RenderSettings& settings, RenderStats& stats);

// The relative cost of rendering each row of the film, from a pilot that traces sample 0 of a
// sparse grid of pixels (about 16,000 of them): for each row, the rays its pixels trace, with
// a small cost for pixels the camera does not see. Deterministic (integer counts of the same
// sample paths the render traces), so every piece of a split render computes the same costs.
// Uses settings.seed and settings.threads only.
std::vector<uint64_t> estimateRowCosts(const Scene& scene, const RenderSettings& settings);

}  // namespace columba
