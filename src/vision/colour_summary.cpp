#include "vision/colour_summary.h"

#include <stdexcept>
#include <string>

namespace columba {

ColourSummary colourSummary(const std::vector<float>& lambdas, const std::vector<float>& values, float lo, float hi) {
  ColourSummary s;
  double largest = 0.0, smallest = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < lambdas.size() && i < values.size(); ++i) {
    if (lambdas[i] < lo || lambdas[i] > hi) continue;
    const double v = values[i];
    if (count == 0 || v > largest) largest = v, s.H1 = lambdas[i];
    if (count == 0 || v < smallest) smallest = v;
    s.B1 += v;
    ++count;
  }
  if (count == 0)
    throw std::invalid_argument("no wavelength of the spectrum lies in " + std::to_string(lo) + "-" +
                                std::to_string(hi) + " nm");
  s.B2 = s.B1 / double(count);
  if (!(s.B2 > 0.0)) throw std::invalid_argument("the spectrum's mean is not positive: its chroma S8 has no value");
  s.S8 = (largest - smallest) / s.B2;
  return s;
}

}  // namespace columba
