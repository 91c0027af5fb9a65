#include "vision/quantum_catch.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace columba {

namespace {

void checkSize(const Observer& observer, const std::vector<float>& spectrum, const char* what) {
  if (spectrum.size() != observer.grid.count)
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(spectrum.size()) + " samples, observer '" +
                                observer.name + "' " + std::to_string(observer.grid.count));
}

double catchOf(const std::vector<float>& sensitivity, const std::vector<float>& reflectance,
               const std::vector<float>& illuminant, double step) {
  double sum = 0.0;
  for (std::size_t i = 0; i < sensitivity.size(); ++i)
    sum += double(reflectance[i]) * double(illuminant[i]) * double(sensitivity[i]);
  return sum * step;
}

}  // namespace

ConeCatches quantumCatches(const Observer& observer, const std::vector<float>& reflectance,
                           const std::vector<float>& illuminant) {
  checkSize(observer, reflectance, "the reflectance");
  checkSize(observer, illuminant, "the illuminant");
  ConeCatches catches;
  for (const std::vector<float>& s : observer.sensitivities)
    catches.chromatic.push_back(catchOf(s, reflectance, illuminant, observer.grid.stepNm));
  if (observer.hasAchromatic())
    catches.achromatic = catchOf(observer.achromatic, reflectance, illuminant, observer.grid.stepNm);
  return catches;
}

ConeCatches backgroundCatches(const Observer& observer, const std::vector<float>& illuminant,
                              const std::vector<float>& background) {
  const ConeCatches catches = quantumCatches(
      observer, background.empty() ? std::vector<float>(observer.grid.count, 1.0f) : background, illuminant);
  auto check = [&](double q, const std::string& cone) {
    if (!(q > 0.0 && std::isfinite(q)))
      throw std::invalid_argument(fmt::format(
          "observer '{}': the background's catch in {} is {:g}, so nothing can be adapted to it: the illuminant (or "
          "background) has no light where that cone is sensitive",
          observer.name, cone, q));
  };
  for (size_t c = 0; c < catches.chromatic.size(); ++c) check(catches.chromatic[c], observer.channels[c]);
  if (catches.achromatic) check(*catches.achromatic, observer.achromaticChannel);
  return catches;
}

ConeCatches vonKries(const ConeCatches& catches, const ConeCatches& background) {
  if (catches.chromatic.size() != background.chromatic.size())
    throw std::invalid_argument("von Kries adaptation: the background has a different number of channels");
  ConeCatches adapted;
  for (std::size_t i = 0; i < catches.chromatic.size(); ++i)
    adapted.chromatic.push_back(catches.chromatic[i] / background.chromatic[i]);
  if (catches.achromatic && background.achromatic) adapted.achromatic = *catches.achromatic / *background.achromatic;
  return adapted;
}

ConeCatches adaptedQuantumCatches(const Observer& observer, const std::vector<float>& reflectance,
                                  const std::vector<float>& illuminant, const std::vector<float>& background) {
  return vonKries(quantumCatches(observer, reflectance, illuminant),
                  backgroundCatches(observer, illuminant, background));
}

std::vector<double> relativeCatches(const std::vector<double>& chromatic) {
  double sum = 0.0;
  for (double q : chromatic) sum += q;
  std::vector<double> relative;
  for (double q : chromatic) relative.push_back(sum > 0.0 ? q / sum : 0.0);
  return relative;
}

std::vector<float> equalQuantumSpectrum(const SpectralGrid& grid, float value) {
  return std::vector<float>(grid.count, value);
}

}  // namespace columba
