#pragma once
// The uniform wavelength grid on which the visual models tabulate sensitivities and take spectra.
#include <cstddef>
#include <functional>
#include <vector>

namespace columba {

// Wavelengths firstNm, firstNm + stepNm, ..., count of them. Integrals over the grid are sums of
// samples times stepNm (each sample stands for one step), the rule pavo's vismodel and sensmodel
// use on their 1 nm grids, so catches and normalisations agree with theirs sample for sample.
struct SpectralGrid {
  double firstNm = 300.0;
  double stepNm = 1.0;
  std::size_t count = 531;

  double wavelength(std::size_t i) const { return firstNm + stepNm * double(i); }
  double lastNm() const { return wavelength(count - 1); }
  // The grid from firstNm to lastNm (inclusive) in steps of stepNm.
  static SpectralGrid span(double firstNm, double lastNm, double stepNm = 1.0);
};

// 300-830 nm in 1 nm steps: birds see from 300 nm, and the CIE tables stop at 830 nm.
SpectralGrid visionGrid();

// The sum of values times the grid step; throws std::invalid_argument where the sizes differ.
double integrateOnGrid(const SpectralGrid& grid, const std::vector<float>& values);

// Values given at increasing wavelengths `x` (nm), linear between them and 0 outside, at `t`.
double interpolateTabulated(const std::vector<double>& x, const std::vector<double>& y, double t);
// f at each wavelength of the grid.
std::vector<float> tabulateOnGrid(const SpectralGrid& grid, const std::function<double(double)>& f);

}  // namespace columba
