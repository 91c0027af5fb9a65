#pragma once
// The colour summary variables of a reflectance spectrum as pavo's summary.rspec computes them,
// after Montgomerie (2006), "Analyzing colors", in Hill & McGraw (eds.), Bird Coloration vol. 1:
// B1 total brightness (the sum of the values), B2 mean brightness, S8 chroma ((Rmax - Rmin) / B2)
// and H1 hue (the wavelength of the largest value, the first where several are equal), over the
// spectrum's wavelengths within [lo, hi] nm (pavo's usual 300-700 nm, at its 1 nm steps).
#include <vector>

namespace columba {

struct ColourSummary {
  double B1 = 0.0, B2 = 0.0, S8 = 0.0, H1 = 0.0;
};

// `lambdas` increasing, one value each; throws std::invalid_argument where no wavelength lies in
// [lo, hi] or the mean there is not positive (S8 has no value).
ColourSummary colourSummary(const std::vector<float>& lambdas, const std::vector<float>& values, float lo = 300.0f,
                            float hi = 700.0f);

}  // namespace columba
