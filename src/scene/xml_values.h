#pragma once
// Strict conversions of scene-file text into numbers, vectors and spectra. Each failure is an
// InputError at `loc` that quotes the offending text and names `what` it was for, e.g.
// "<float> 'fov'".
#include <string>
#include <vector>
#include "core/error.h"
#include "core/spectrum.h"
#include "core/vector.h"

namespace columba {

// A decimal number within the range of a float; the whole text must be the number (surrounding
// spaces aside).
double parseFloat(const std::string& text, const std::string& what, const SourceLocation& loc);
long long parseInteger(const std::string& text, const std::string& what, const SourceLocation& loc);
// "true" or "false", in any letter case.
bool parseBoolean(const std::string& text, const std::string& what, const SourceLocation& loc);
// Numbers separated by commas and/or white space.
std::vector<double> parseFloatList(const std::string& text, const std::string& what, const SourceLocation& loc);
// "x, y, z", or a single number used for all three components.
Vec3 parseVec3(const std::string& text, const std::string& what, const SourceLocation& loc);
// A spectrum as a scene file gives it, with its smallest value (negative values are an error only
// for some uses, such as emission).
struct GivenSpectrum {
  SpectralDistribution distribution;
  float lowest = 0.0f;
};

// "30" (constant) or "400:0.78, 500:0.8, ..." (piecewise linear; wavelengths in nm, increasing).
GivenSpectrum parseSpectrum(const std::string& text, const std::string& what, const SourceLocation& loc);
// A regular text file of "wavelength value" lines ('#' starts a comment). Errors point at the
// file's own line; `loc` is used when the file is missing, not a regular file or unreadable.
GivenSpectrum readSpectrumFile(const std::string& path, const std::string& what, const SourceLocation& loc);

}  // namespace columba
