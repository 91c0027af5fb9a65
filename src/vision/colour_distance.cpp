#include "vision/colour_distance.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace columba {

std::vector<double> receptorNoise(const ReceptorNoise& noise) {
  checkReceptorNoise(noise);
  const std::vector<double>& eta = noise.relativeDensities;
  std::vector<double> e;
  for (double density : eta) e.push_back(noise.weberFraction * std::sqrt(eta[noise.weberReference] / density));
  return e;
}

double chromaticDistance(const std::vector<double>& catchesA, const std::vector<double>& catchesB,
                         const std::vector<double>& noise) {
  std::size_t n = noise.size();
  if (n < 2 || catchesA.size() != n || catchesB.size() != n)
    throw std::invalid_argument("a chromatic distance needs two or more channels, as many catches as noise values");
  std::vector<double> df(n), e2(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(catchesA[i] > 0.0) || !(catchesB[i] > 0.0))
      throw std::invalid_argument("the receptor-noise model takes logarithms of catches, which must be positive");
    df[i] = std::log(catchesA[i]) - std::log(catchesB[i]);
    e2[i] = noise[i] * noise[i];
  }
  // Products of e_k^2 over all k but one (i) or two (i, j) channels, without dividing (an e may be 0).
  auto productWithout = [&](std::size_t i, std::size_t j) {
    double p = 1.0;
    for (std::size_t k = 0; k < n; ++k)
      if (k != i && k != j) p *= e2[k];
    return p;
  };
  double numerator = 0.0, denominator = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    denominator += productWithout(i, i);
    for (std::size_t j = i + 1; j < n; ++j) {
      double d = df[i] - df[j];
      numerator += productWithout(i, j) * d * d;
    }
  }
  return std::sqrt(numerator / denominator);
}

double achromaticDistance(double catchA, double catchB, double achromaticWeberFraction) {
  if (!(catchA > 0.0) || !(catchB > 0.0)) throw std::invalid_argument("achromatic catches must be positive");
  return std::abs(std::log(catchA) - std::log(catchB)) / achromaticWeberFraction;
}

double chromaticDistance(const Observer& observer, const ConeCatches& a, const ConeCatches& b) {
  return chromaticDistance(a.chromatic, b.chromatic, receptorNoise(observer.noise));
}

double achromaticDistance(const Observer& observer, const ConeCatches& a, const ConeCatches& b) {
  if (!a.achromatic || !b.achromatic)
    throw std::invalid_argument("observer '" + observer.name + "' has no achromatic channel");
  return achromaticDistance(*a.achromatic, *b.achromatic, observer.noise.achromaticWeberFraction);
}

}  // namespace columba
