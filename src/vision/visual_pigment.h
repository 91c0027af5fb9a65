#pragma once
// The absorbance of a vitamin-A1 visual pigment as a function of wavelength, from its wavelength of
// peak absorbance alone: the template of Govardovskii, Fyhrquist, Reuter, Kuzmin & Donner (2000),
// "In search of the visual pigment template", Visual Neuroscience 17:509-528.
#include <vector>

#include "vision/spectral_grid.h"

namespace columba {

// The alpha band (the main peak), normalised to about 1 at lambdaMaxNm. With x = lambdaMax / lambda:
//   S(x) = 1 / (exp(A (a - x)) + exp(B (b - x)) + exp(C (c - x)) + D),
//   A = 69.7, a = 0.8795 + 0.0459 exp(-(lambdaMax - 300)^2 / 11940), B = 28, b = 0.922,
//   C = -14.9, c = 1.104, D = 0.674.
double govardovskiiAlphaBand(double lambdaMaxNm, double lambdaNm);

// The beta band (the cis-band in the near ultraviolet), a Gaussian in wavelength:
//   S(lambda) = A_beta exp(-((lambda - lambda_beta) / b_beta)^2),
//   A_beta = 0.26, lambda_beta = 189 + 0.315 lambdaMax, b_beta = -40.5 + 0.195 lambdaMax.
double govardovskiiBetaBand(double lambdaMaxNm, double lambdaNm);

// Alpha band, plus the beta band where withBetaBand.
double govardovskiiA1(double lambdaMaxNm, double lambdaNm, bool withBetaBand = true);

// The template on a grid, divided by its largest sample (peak 1), as pavo's sensmodel does before it
// applies an oil droplet.
std::vector<float> visualPigmentAbsorbance(const SpectralGrid& grid, double lambdaMaxNm, bool withBetaBand = true);

}  // namespace columba
