#include "barbule/layer_stacks.h"

namespace columba {

const std::vector<LayerStackPreset>& layerStackPresets() {
  static const std::vector<LayerStackPreset> presets = {
      // Seven melanin layers, the upper end of the abstract's "6-7", which with six spacers makes
      // 2.6 um of the barbule's ~3 um; the cortex above them is the barbule's own film (`height`),
      // which the abstract does not give. Its melanin is treated as homogeneous layers of
      // melanin's own index, as the abstract's "effectively ~0.2 um thick melanin layers" does.
      {"parotia-occipital",
       "Stavenga, Leertouwer, Osorio & Wilts 2015 (Light: Science & Applications 4, e243; DOI "
       "10.1038/lsa.2015.16), abstract: occipital-feather barbules of Lawes' parotia, ~3 um thick, with 6-7 "
       "layers of melanin rodlets forming effectively ~0.2 um melanin layers separated by ~0.2 um keratin "
       "layers; measured reflectance peak ~1.3 um",
       "[melanin:0.2, keratin:0.2] x 6, melanin:0.2"},
  };
  return presets;
}

std::string expandLayerStack(const std::string& text) {
  for (const LayerStackPreset& preset : layerStackPresets())
    if (text == preset.name) return preset.layers;
  return text;
}

}  // namespace columba
