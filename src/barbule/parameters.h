#pragma once
// The barbule BSDF's parameters: their defaults (the paper's reference scenes), presets for rock
// dove barbules with their sources, and the checks every way of setting them shares (the scene
// plug-in, `columba bsdf`).
#include <optional>
#include <string>
#include <vector>
#include "core/spectrum.h"
#include "core/surface_attributes.h"
#include "optics/dispersion.h"
#include "optics/layered_film.h"

namespace columba {

struct BarbuleParameters {
  float b = 0.25f;      // cross-section semi-axis along n (the one across is 1)
  float phi0 = -0.37f;  // reflective arc, normal angles in the cross-section's own frame (rad)
  float phi1 = 2.64f;
  float mu = -0.35f;             // tilt of the cross-section about the barbule axis (rad)
  float H = 1.25f;               // barbule spacing, in units of the across semi-axis
  float profileExponent = 2.0f;  // superellipse exponent of the cross-section: 2, the ellipse
  float height = 0.6f;           // keratin cortex (film) thickness, micrometres
  RefractiveIndex filmIOR = RefractiveIndex::keratin();
  float extIOR = 1.000277f;  // air
  // Intensity reflectance of the melanin layer under the film; the embedded measured table
  // (optics/melanin.h) when empty.
  std::optional<SpectralDistribution> melanin;
  // Layers under the cortex, from the cortex down (docs/model.md, "Layered films"); none: the
  // cortex alone, the paper's film.
  FilmStack layersBelow;
  // Further stacks, which a feather's per-vertex `stack` chooses by number (the scene's layers_1,
  // layers_2, ...); stack 0 is layersBelow.
  std::vector<FilmStack> numberedLayerStacks;

  int layerStackCount() const { return 1 + int(numberedLayerStacks.size()); }
  // Stack `index`, 0 to layerStackCount() - 1.
  const FilmStack& layerStack(int index) const {
    return index == 0 ? layersBelow : numberedLayerStacks[size_t(index - 1)];
  }
};

// Most layer stacks one barbule BSDF holds: layers and layers_1 to layers_15.
inline constexpr int kMaxLayerStacks = 16;

// The parameters a shape may give per point (a feather's per-vertex values), under their names
// in a scene file.
inline const SurfaceAttributeKey kBarbuleSpacingAttribute{"H"};
inline const SurfaceAttributeKey kBarbuleTiltAttribute{"mu"};
inline const SurfaceAttributeKey kCortexThicknessAttribute{"height"};
// The layer stack a point chooses, by number (BarbuleParameters::layerStack): not interpolated,
// the nearest vertex's.
inline const SurfaceAttributeKey kLayerStackAttribute{"stack"};

// A named set of shape parameters and film thickness, with where the values come from.
struct BarbulePreset {
  const char* name;
  const char* source;
  float b, phi0, phi1, mu, H, height;
};
const std::vector<BarbulePreset>& barbulePresets();
// The preset's parameters (the rest at their defaults); nullopt for an unknown name.
std::optional<BarbuleParameters> barbulePreset(const std::string& name);
// "dove-green, dove-purple": for messages.
std::string barbulePresetNames();

// What is wrong with a parameter set, naming the parameter as the scene plug-in spells it.
struct BarbuleParameterProblem {
  std::string parameter, message;
};
std::optional<BarbuleParameterProblem> findProblem(const BarbuleParameters& p);
// Values that are valid but probably a mistake (a film thickness given in nanometres).
std::optional<BarbuleParameterProblem> findImplausibility(const BarbuleParameters& p);

}  // namespace columba
