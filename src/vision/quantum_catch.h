#pragma once
// Cone quantum catches of a reflectance under an illuminant, as pavo's vismodel computes them
// (qcatch = "Qi"), with von Kries adaptation to a background as an option.
#include <optional>
#include <vector>

#include "vision/observer.h"

namespace columba {

// One catch per chromatic channel of the observer, and the achromatic catch where it has one.
struct ConeCatches {
  std::vector<double> chromatic;
  std::optional<double> achromatic;
};

// Q_i = integral of R(lambda) I(lambda) S_i(lambda) dlambda over the observer's grid, for a
// reflectance R and an illuminant I (in photon units) sampled on that grid.
ConeCatches quantumCatches(const Observer& observer, const std::vector<float>& reflectance,
                           const std::vector<float>& illuminant);

// The catches of an ideal white (R = 1) under the illuminant, or of the given background spectrum.
// Throws std::invalid_argument naming the cone where one is not positive and finite (an illuminant
// dark where that cone is sensitive): nothing could be adapted to it.
ConeCatches backgroundCatches(const Observer& observer, const std::vector<float>& illuminant,
                              const std::vector<float>& background = {});

// von Kries adaptation: q_i = Q_i / Q_i,background for every channel, the achromatic one included.
// (pavo leaves its achromatic catch unadapted; the achromatic contrast is the same either way.)
ConeCatches vonKries(const ConeCatches& catches, const ConeCatches& background);

// The catches adapted to the background (ideal white where background is empty): vismodel with
// qcatch = "Qi", vonkries = TRUE, relative = FALSE.
ConeCatches adaptedQuantumCatches(const Observer& observer, const std::vector<float>& reflectance,
                                  const std::vector<float>& illuminant, const std::vector<float>& background = {});

// The chromatic catches divided by their sum (vismodel's relative = TRUE).
std::vector<double> relativeCatches(const std::vector<double>& chromatic);

// A spectrum of equal photon flux at every wavelength, 1 per nm (pavo's "ideal" illuminant).
std::vector<float> equalQuantumSpectrum(const SpectralGrid& grid, float value = 1.0f);

}  // namespace columba
