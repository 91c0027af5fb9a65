#include "fit/scene_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "builtin/builtin_plugins.h"
#include "core/quiet_warnings.h"
#include "film/film.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace columba {

namespace {

// The built-in plug-ins with every hdrfilm resized to width x height (after the scene's own
// values are checked), so the render matches the target pixel for pixel.
PluginRegistry registryWithFilmSize(int width, int height) {
  PluginRegistry registry = builtinPlugins();
  registry.add("film", "hdrfilm", [width, height](const Properties& props) -> std::shared_ptr<Object> {
    return std::static_pointer_cast<Film>(makeHDRFilm(props))->resized(width, height);
  });
  return registry;
}

Defines definesWith(const SceneFitSettings& settings, const std::vector<double>& values) {
  Defines defines = settings.defines;
  for (size_t i = 0; i < values.size(); ++i) defines[settings.parameters[i].name] = fmt::format("{:.9g}", values[i]);
  return defines;
}

std::vector<float> maskWeights(const SceneFitSettings& settings) {
  if (!settings.mask) return {};
  const Image& mask = *settings.mask;
  if (mask.width != settings.target.width || mask.height != settings.target.height)
    throw std::runtime_error(fmt::format("the mask is {}x{} pixels, the target {}x{}", mask.width, mask.height,
                                         settings.target.width, settings.target.height));
  std::vector<float> weights(mask.rgb.size());
  for (size_t p = 0; p < weights.size() / 3; ++p) {
    const float* m = &mask.rgb[3 * p];
    const float w = std::max({m[0], m[1], m[2]}) >= 0.5f ? 1.0f : 0.0f;
    weights[3 * p] = weights[3 * p + 1] = weights[3 * p + 2] = w;
  }
  return weights;
}

}  // namespace

Image renderSceneWith(const SceneFitSettings& settings, const std::vector<double>& values) {
  const PluginRegistry registry = registryWithFilmSize(settings.target.width, settings.target.height);
  const Defines defines = definesWith(settings, values);
  ParsedScene parsed = loadSceneFile(settings.scenePath, defines, registry);
  for (const FitParameter& p : settings.parameters)
    if (std::find(parsed.unusedDefines.begin(), parsed.unusedDefines.end(), p.name) != parsed.unusedDefines.end())
      throw std::runtime_error(fmt::format("{}: the scene uses no variable ${}, so --vary {} cannot change it",
                                           settings.scenePath, p.name, p.name));
  Scene scene(parsed, SourceLocation{settings.scenePath, 0});
  const Film& film = scene.sensor().film();
  if (film.width() != settings.target.width || film.height() != settings.target.height)
    throw std::runtime_error(
        fmt::format("{}: the film is {}x{} and could not be set to the target's {}x{} "
                    "(give the sensor an <film type=\"hdrfilm\">)",
                    settings.scenePath, film.width(), film.height(), settings.target.width, settings.target.height));
  RenderSettings render;
  render.samplesPerPixel = settings.samplesPerPixel;
  render.seed = settings.seed;
  render.threads = settings.threads;
  RenderStats stats;
  return renderImage(scene, render, stats);
}

SceneFitResult fitScene(const SceneFitSettings& settings) {
  std::vector<std::string> fixed;
  for (const auto& define : settings.defines) fixed.push_back(define.first);
  checkFitSettings(settings.parameters, settings.fit, fixed);
  if (settings.samplesPerPixel < 0)
    throw std::invalid_argument(
        fmt::format("samples per pixel must be 0 (the scene's sampler) or more, not {}", settings.samplesPerPixel));
  if (settings.threads < 0)
    throw std::invalid_argument(fmt::format("threads must be 0 (all cores) or more, not {}", settings.threads));
  ScaledLoss loss(settings.target.rgb, maskWeights(settings), settings.loss, settings.scale);
  // The scene's warnings are shown by the first evaluation only.
  std::optional<QuietWarnings> quiet;
  SceneFitResult result;
  result.fit = runFit(
      settings.parameters,
      [&](const std::vector<double>& values) {
        LossValue value = loss(renderSceneWith(settings, values).rgb);
        if (!quiet) quiet.emplace();
        return value;
      },
      settings.fit);
  result.render = renderSceneWith(settings, result.fit.values);
  return result;
}

}  // namespace columba
