#include "vision/spectral_grid.h"

#include <algorithm>

#include <cmath>
#include <stdexcept>
#include <string>

namespace columba {

SpectralGrid SpectralGrid::span(double firstNm, double lastNm, double stepNm) {
  if (!(stepNm > 0.0) || !(lastNm >= firstNm))
    throw std::invalid_argument("a spectral grid needs a positive step and an end at or after its start");
  double steps = (lastNm - firstNm) / stepNm;
  auto count = std::size_t(std::llround(steps)) + 1;
  if (std::abs(steps - double(count - 1)) > 1e-6)
    throw std::invalid_argument("the grid's span " + std::to_string(lastNm - firstNm) +
                                " nm is not a whole number of steps");
  return {firstNm, stepNm, count};
}

SpectralGrid visionGrid() { return SpectralGrid::span(300.0, 830.0, 1.0); }

double integrateOnGrid(const SpectralGrid& grid, const std::vector<float>& values) {
  if (values.size() != grid.count)
    throw std::invalid_argument("a spectrum of " + std::to_string(values.size()) + " samples on a grid of " +
                                std::to_string(grid.count));
  double sum = 0.0;
  for (float v : values) sum += double(v);
  return sum * grid.stepNm;
}

std::vector<float> tabulateOnGrid(const SpectralGrid& grid, const std::function<double(double)>& f) {
  std::vector<float> values(grid.count);
  for (std::size_t i = 0; i < grid.count; ++i) values[i] = float(f(grid.wavelength(i)));
  return values;
}

double interpolateTabulated(const std::vector<double>& x, const std::vector<double>& y, double t) {
  if (x.empty() || t < x.front() || t > x.back()) return 0.0;
  const size_t i = std::min(size_t(std::upper_bound(x.begin(), x.end(), t) - x.begin()), x.size() - 1);
  if (i == 0) return y.front();
  const double f = (t - x[i - 1]) / (x[i] - x[i - 1]);
  return (1.0 - f) * y[i - 1] + f * y[i];
}

}  // namespace columba
