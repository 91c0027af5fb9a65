#pragma once
// Smooth spectra for the colours of an image or a mesh, one Jakob-Hanika fit per distinct colour:
// images and coloured meshes repeat colours a great deal, and each fit is an iterative solve.
#include <vector>
#include "core/spectrum.h"

namespace columba {

struct FittedColours {
  std::vector<RGBSpectrum> spectra;  // one per colour, in order
  float mean = 0.0f;                 // the mean over the colours of each spectrum's visible-range mean
};

// Colours above 1 are fitted unbounded (fitRGBSpectrum). The fits run in parallel; the result does
// not depend on their order.
FittedColours fitColourSpectra(const std::vector<Vec3>& colours);

}  // namespace columba
