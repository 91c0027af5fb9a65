#pragma once
// CIE standard illuminant D65, the white of Mitsuba's spectral conventions: a single-valued or
// RGB emitter spectrum is D65 scaled to the given luminance, so a white surface under a white
// light is (1, 1, 1) in linear sRGB.

#include "core/spectrum.h"

namespace columba {

// D65's relative spectral power at `lambda` (nm), scaled so that its luminance
// (integral of S ybar over the integral of ybar, 360-830 nm) is 1.
float d65(float lambda);
// The same at a path's wavelengths.
Spectrum d65(const Wavelengths& wl);

}  // namespace columba
