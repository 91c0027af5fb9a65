#pragma once
// Smooth spectra for the many colours of an environment map or an HDR image, read from a table
// instead of fitted one by one. A colour c is taken, as Mitsuba takes an emitted or unbounded
// colour, as 2m times the spectrum of c / (2m), m its largest component: that spectrum's colour has
// one component 1/2 and two ratios to it in [0, 1], so a table over those two ratios (one per
// largest channel) holds every such spectrum. Coefficients are fitted at 64 x 64 ratios per channel
// once per run and interpolated bilinearly between them, as Jakob & Hanika (2019) interpolate theirs.
#include <cstddef>
#include <vector>
#include "core/spectrum.h"

namespace columba {

// The spectrum of `rgb` (components below zero taken as zero) from the table: its colour under
// D65 is rgb to within the accuracy tests/core/test_rgb_spectrum_table.cpp states. Thread-safe; the
// first call builds the table (about 12,000 fits, each from its neighbour's coefficients).
RGBSpectrum tabulatedRGBSpectrum(const Vec3& rgb);
// The spectra of `count` colours stored as consecutive r, g, b floats (an image's pixels, a grid's
// voxels), each as tabulatedRGBSpectrum gives it, looked up in parallel.
std::vector<RGBSpectrum> tabulatedRGBSpectra(const float* rgb, size_t count);

}  // namespace columba
