#pragma once
// What a render is of: the options `columba render` and `columba slurm` share, the frames they
// plan from them and each frame's scene.
#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "distribute/frame_plan.h"
#include "scene/scene_loader.h"

namespace columba {

struct SceneOptions {
  std::string scenePath;
  std::vector<std::string> defines;
  std::string spp;  // checked by parseCount, so that every value gets the same message
  uint64_t seed = 0;
  bool spectral = false;  // radiance per wavelength bin in the EXR besides RGB
  std::string bins = "16";
  std::string spectralRange;  // LO:HI nm for the bins; "": the whole range the film renders
  std::vector<std::string> sweeps;
  std::string framesPattern;
};
void addSceneOptions(CLI::App* command, SceneOptions& options);
// --spectral-range's LO:HI as (LO, HI) nm, within 300-830 (0, 0 for ""); std::runtime_error naming
// the option and the text otherwise. Whether the film renders that range is the renderer's check.
std::pair<float, float> parseSpectralRange(const std::string& text);

// The frames of a render to `output` (-o, or "" for the scene's name in the working directory);
// throws std::runtime_error for a bad sweep, pattern, output name or scene path, before any work.
FramePlan planFrames(const SceneOptions& options, const std::string& output);
// A frame's scene with its -D values (`defines`), loaded as `columba render` loads it (the
// built-in scene when options.scenePath is empty), and the name messages give it.
ParsedScene loadFrameScene(const SceneOptions& options, const Defines& defines);
SourceLocation frameSceneSource(const SceneOptions& options);

}  // namespace columba
