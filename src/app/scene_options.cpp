#include "app/scene_options.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

#include "builtin/builtin_plugins.h"
#include "builtin/default_scene.h"
#include "builtin/default_scene_xml.h"
#include "core/number_text.h"
#include "core/spectrum.h"
#include "render/renderer.h"
#include "samplers/sampler_parameters.h"

namespace columba {

namespace {

std::string readSceneText(const std::string& scenePath) {
  if (scenePath.empty()) return kDefaultSceneXML;
  std::ifstream in(scenePath, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

FramePlan planFrames(const SceneOptions& options, const std::string& output) {
  if (!options.scenePath.empty() && !std::filesystem::is_regular_file(options.scenePath))
    throw std::runtime_error("scene file '" + options.scenePath + "' does not exist or is not a regular file");
  return planFrames(FrameRequest{options.scenePath, readSceneText(options.scenePath), options.defines, options.sweeps,
                                 options.framesPattern, output});
}

ParsedScene loadFrameScene(const SceneOptions& options, const Defines& defines) {
  return options.scenePath.empty() ? loadDefaultScene(defines)
                                   : loadSceneFile(options.scenePath, defines, builtinPlugins());
}

SourceLocation frameSceneSource(const SceneOptions& options) {
  return {options.scenePath.empty() ? "<default scene>" : options.scenePath, 0};
}

std::pair<float, float> parseSpectralRange(const std::string& text) {
  if (text.empty()) return {0.0f, 0.0f};
  const size_t colon = text.find(':');
  const std::optional<float> lo = parseNumber<float>(text.substr(0, colon)),
                             hi =
                                 colon == std::string::npos ? std::nullopt : parseNumber<float>(text.substr(colon + 1));
  if (!lo || !hi || !(*lo >= kSpectralMin && *lo < *hi && *hi <= kLambdaMax))
    throw std::runtime_error(fmt::format("--spectral-range '{}': give LO:HI in nm, {:g} <= LO < HI <= {:g}", text,
                                         kSpectralMin, kLambdaMax));
  return {*lo, *hi};
}

void addSceneOptions(CLI::App* cmd, SceneOptions& options) {
  cmd->add_option("scene", options.scenePath, "Scene file (XML); none: the built-in default scene");
  cmd->add_option("-D,--define", options.defines, "Set a scene parameter: -D name=value (repeatable)")
      ->allow_extra_args(false);  // one name=value per -D, so that a scene file may follow
  cmd->add_option("--spp", options.spp,
                  fmt::format("Samples per pixel, 1 to {} (default: the scene's sampler)", kMaxSamplesPerPixel));
  cmd->add_option("--seed", options.seed, "Random seed; the same seed gives the same image");
  auto* spectral =
      cmd->add_flag("--spectral", options.spectral,
                    "Also write radiance per wavelength bin into the EXR (channels S0.<centre>nm), over the whole "
                    "range the film renders unless --spectral-range says otherwise");
  cmd->add_option("--bins", options.bins,
                  fmt::format("Wavelength bins for --spectral, 1 to {} (default 16)", kMaxSpectralBins));
  cmd->add_option("--spectral-range", options.spectralRange,
                  "LO:HI nm, the bins' range within 300-830 (default: what the film renders, 360-830 nm for an RGB "
                  "film, its observer's range for a bird's)")
      ->needs(spectral);
  cmd->add_option("--sweep", options.sweeps,
                  "Render one frame per value of a scene variable: NAME=START:STOP:STEP (STOP included) or "
                  "NAME=v1,v2,...; several --sweep form a grid (the first varies slowest)")
      ->allow_extra_args(false);
  cmd->add_option("--frames", options.framesPattern,
                  "The frames' file names: %d or %03d is the frame index, {NAME} a swept value, {NAME:03} the "
                  "value formatted (default: OUT_NAME=VALUE.exr from -o)");
}

}  // namespace columba
