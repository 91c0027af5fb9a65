#pragma once
// Receptor-noise-limited colour distances (Vorobyev & Osorio 1998, "Receptor noise as a determinant
// of colour thresholds", Proc R Soc Lond B 265:351-358), in just noticeable differences (JND), as
// pavo's coldist computes them with noise = "neural".
#include <vector>

#include "vision/observer.h"
#include "vision/quantum_catch.h"

namespace columba {

// e_i = weber * sqrt(eta_ref / eta_i): the noise of each chromatic channel from the Weber fraction of
// the reference cone and the relative densities eta.
std::vector<double> receptorNoise(const ReceptorNoise& noise);

// The chromatic distance between two sets of catches, on the log signals f_i = ln q_i, for n >= 2
// channels with noise e:
//   dS^2 = sum over pairs i < j of (prod over k not in {i, j} of e_k)^2 (df_i - df_j)^2
//          / sum over i of (prod over k != i of e_k)^2,
// with df_i = f_i(a) - f_i(b). For n = 2, 3, 4 these are Vorobyev & Osorio's dichromat, trichromat and
// tetrachromat formulas. Throws std::invalid_argument for mismatched sizes or non-positive catches.
double chromaticDistance(const std::vector<double>& catchesA, const std::vector<double>& catchesB,
                         const std::vector<double>& noise);

// The achromatic distance |ln L_a - ln L_b| / weber of two achromatic (double cone) catches.
double achromaticDistance(double catchA, double catchB, double achromaticWeberFraction);

// dS with the observer's receptor noise.
double chromaticDistance(const Observer& observer, const ConeCatches& a, const ConeCatches& b);
// dL with the observer's achromatic Weber fraction; throws where the catches have no achromatic value.
double achromaticDistance(const Observer& observer, const ConeCatches& a, const ConeCatches& b);

}  // namespace columba
