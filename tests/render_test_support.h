#pragma once
// Renders scene XML held in a string, for tests of whole-image behaviour.
#include <string>
#include "render/renderer.h"
#include "scene/scene.h"

namespace columba::testing {

inline Image renderSceneString(const std::string& xml, const RenderSettings& settings = {}, RenderStats* statsOut = nullptr) {
  ParsedScene parsed = loadSceneString(xml, "<test scene>", ".", {}, PluginRegistry::builtin());
  Scene scene(parsed, SourceLocation{"<test scene>", 0});
  RenderStats stats;
  Image image = renderImage(scene, settings, stats);
  if (statsOut) *statsOut = stats;
  return image;
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

}  // namespace columba::testing
