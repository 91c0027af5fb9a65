#include "vision/visual_pigment.h"

#include <algorithm>
#include <cmath>

namespace columba {

// The A1 constants of Govardovskii et al. (2000), as listed in visual_pigment.h; each was checked
// against pavo's template (R/sensmodel-templates.R, pavo 2.10), which restates the paper's alpha band
// after Stavenga (2010) and its beta band as published.
double govardovskiiAlphaBand(double lambdaMaxNm, double lambdaNm) {
  constexpr double A = 69.7, B = 28.0, b = 0.922, C = -14.9, c = 1.104, D = 0.674;
  double d = lambdaMaxNm - 300.0;
  double a = 0.8795 + 0.0459 * std::exp(-d * d / 11940.0);
  double x = lambdaMaxNm / lambdaNm;
  return 1.0 / (std::exp(A * (a - x)) + std::exp(B * (b - x)) + std::exp(C * (c - x)) + D);
}

double govardovskiiBetaBand(double lambdaMaxNm, double lambdaNm) {
  constexpr double amplitude = 0.26;
  double peak = 189.0 + 0.315 * lambdaMaxNm;
  double width = -40.5 + 0.195 * lambdaMaxNm;
  double t = (lambdaNm - peak) / width;
  return amplitude * std::exp(-t * t);
}

double govardovskiiA1(double lambdaMaxNm, double lambdaNm, bool withBetaBand) {
  double s = govardovskiiAlphaBand(lambdaMaxNm, lambdaNm);
  return withBetaBand ? s + govardovskiiBetaBand(lambdaMaxNm, lambdaNm) : s;
}

std::vector<float> visualPigmentAbsorbance(const SpectralGrid& grid, double lambdaMaxNm, bool withBetaBand) {
  std::vector<double> s(grid.count);
  for (std::size_t i = 0; i < grid.count; ++i) s[i] = govardovskiiA1(lambdaMaxNm, grid.wavelength(i), withBetaBand);
  double peak = s.empty() ? 1.0 : *std::max_element(s.begin(), s.end());
  std::vector<float> out(grid.count);
  for (std::size_t i = 0; i < grid.count; ++i) out[i] = float(s[i] / peak);
  return out;
}

}  // namespace columba
