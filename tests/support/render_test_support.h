#pragma once
// Renders scene XML held in a string, for tests of whole-image behaviour.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>
#include "builtin/builtin_plugins.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace columba::testing {

inline Image renderSceneString(const std::string& xml, const RenderSettings& settings = {},
                               RenderStats* statsOut = nullptr) {
  ParsedScene parsed = loadSceneString(xml, "<test scene>", ".", {}, builtinPlugins());
  Scene scene(parsed, SourceLocation{"<test scene>", 0});
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  if (statsOut) *statsOut = stats;
  return image;
}

// A diffuse plane of `albedo` filling the view of an 8 x 8 camera straight above it (1 degree
// field of view), lit straight from above by a directional light whose irradiance is the
// element `irradiance` (e.g. <spectrum name="irradiance" value="3"/>): L = albedo E / pi.
inline std::string plateUnderDirectionalLight(const std::string& irradiance, float albedo, int spp = 256) {
  return R"(<scene version="3.0.0"><integrator type="direct"/>
    <sensor type="perspective"><float name="fov" value="1"/>
      <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/><rfilter type="box"/></film>
      <sampler type="ldsampler"><integer name="sample_count" value=")" +
         std::to_string(spp) + R"("/></sampler></sensor>
    <shape type="rectangle"><transform name="to_world"><scale value="10"/></transform>
      <bsdf type="diffuse"><float name="reflectance" value=")" +
         std::to_string(albedo) + R"("/></bsdf></shape>
    <emitter type="directional"><vector name="direction" x="0" y="0" z="-1"/>)" +
         irradiance + R"(</emitter>
    </scene>)";
}

// Whether two arrays of floats are the same bit for bit (renders promised deterministic).
inline bool bitIdentical(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}
// Whether two images have the same size and the same colour values bit for bit.
inline bool samePixels(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && bitIdentical(a.rgb, b.rgb);
}

// Mean of each channel over the pixels of [x0, x1) x [y0, y1).
inline Vec3 meanColour(const Image& image, int x0, int y0, int x1, int y1) {
  double sum[3] = {0, 0, 0};
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      for (int c = 0; c < 3; ++c) sum[c] += image.pixel(x, y)[c];
  double n = double(x1 - x0) * (y1 - y0);
  return Vec3(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
}

inline double luminance(const Image& image, int x, int y) {
  const float* c = image.pixel(x, y);
  return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// A mean and its standard error.
struct Estimate {
  double mean = 0, standardError = 0;
};

// How many standard errors apart two estimates are.
inline double standardErrorsApart(const Estimate& a, const Estimate& b) {
  return std::abs(a.mean - b.mean) / std::hypot(a.standardError, b.standardError);
}

// The image's mean luminance over `renders` renders of `xml` with different seeds, and its
// standard error from their spread.
inline Estimate meanLuminanceOverSeeds(const std::string& xml, int renders, uint64_t firstSeed) {
  std::vector<double> means;
  for (int k = 0; k < renders; ++k) {
    RenderSettings settings;
    settings.seed = firstSeed + uint64_t(k);
    Image image = renderSceneString(xml, settings);
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) sum += luminance(image, x, y);
    means.push_back(sum / (image.width * image.height));
  }
  double mean = 0, variance = 0;
  for (double m : means) mean += m / renders;
  for (double m : means) variance += (m - mean) * (m - mean) / (renders - 1);
  return {mean, std::sqrt(variance / renders)};
}

}  // namespace columba::testing
