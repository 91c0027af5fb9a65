#pragma once
// Fits a scene's $variables to a measured image: every evaluation loads the scene with the
// variables set, its film at the target's size, and renders it with the same seed (common random
// numbers), so the loss is a deterministic function of the parameters.
#include <optional>
#include <string>
#include "fit/fit_result.h"
#include "fit/scaled_loss.h"
#include "io/image.h"
#include "scene/scene_loader.h"

namespace columba {

struct SceneFitSettings {
  std::string scenePath;
  Defines defines;  // fixed variables (-D); the fitted ones are set on top
  Image target;
  std::optional<Image> mask;  // the target's size; pixels whose brightest channel is >= 0.5 count
  std::vector<FitParameter> parameters;
  int samplesPerPixel = 0;  // 0: the scene's sampler
  uint64_t seed = 0;
  int threads = 0;  // 0: all hardware threads
  LossKind loss = LossKind::MSE;
  ScaleMode scale = ScaleMode::Free;
  FitSettings fit;
};

struct SceneFitResult {
  FitResult fit;
  Image render;  // at the fitted values, before scaling
};

// Throws std::invalid_argument for settings checkFitSettings refuses (the defines held fixed) or a
// negative sample or thread count; std::runtime_error / InputError naming the file and value for a scene that does not
// use a fitted variable, a mask of another size or a scene that cannot be rendered.
SceneFitResult fitScene(const SceneFitSettings& settings);

// The scene rendered with `values` for the settings' parameters, at the target's size.
Image renderSceneWith(const SceneFitSettings& settings, const std::vector<double>& values);

}  // namespace columba
