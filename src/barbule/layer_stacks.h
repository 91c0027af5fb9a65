#pragma once
// Named stacks of layers under a barbule's cortex, from published measurements of barbules, for
// `barbulebsdf`'s `layers`: each names its publication and what in it the numbers come from.
// docs/model.md, "Layer stacks of other species", compares each stack's reflectance peak with the
// measured one.
#include <string>
#include <vector>

namespace columba {

struct LayerStackPreset {
  const char* name;
  const char* source;  // publication, and where in it the numbers are
  const char* layers;  // as `layers` takes them: "INDEX:THICKNESS, ..." (optics/film_layer_text.h)
};

const std::vector<LayerStackPreset>& layerStackPresets();

// The layers of the named stack when `text` is one of their names, else `text` unchanged.
std::string expandLayerStack(const std::string& text);

}  // namespace columba
