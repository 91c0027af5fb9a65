#include "optics/layered_film.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "optics/melanin_index.h"

namespace columba {

LayerMaterial melanin() {
  LayerMaterial m;
  m.n = RefractiveIndex::cauchy(MelaninIndex::kCauchyA, MelaninIndex::kCauchyB);
  m.k = MelaninIndex::kExtinction;
  m.kDecayNm = MelaninIndex::kExtinctionDecay;
  return m;
}

std::complex<double> FilmLayer::index(float lambdaNm) const {
  if (fraction == 1.0f) return material.index(lambdaNm);
  const std::complex<double> a = material.index(lambdaNm), b = matrix.index(lambdaNm);
  const double f = fraction;
  return std::sqrt(f * a * a + (1.0 - f) * b * b);  // the root with k >= 0
}

LayeredFilm::LayeredFilm(const RefractiveIndex& cortex, float nOutside, float cortexThicknessUm, const FilmStack& below,
                         const Wavelengths& wl) {
  for (int k = 0; k < kSpectrumSamples; ++k) {
    lambdas_[k] = wl[k];
    LayerStack& stack = stacks_[k];
    stack.incidentIndex = nOutside;
    stack.substrateIndex = nOutside;
    stack.layers.reserve(below.layers.size() + 1);  // one allocation a wavelength, at every hit
    stack.layers.push_back({cortex(wl[k]), cortexThicknessUm});
    for (const FilmLayer& layer : below.layers) stack.layers.push_back({layer.index(wl[k]), layer.thicknessUm});
    if (below.runs.empty()) continue;
    // The cortex once, then the stack's own runs (a second allocation, only for stacks that repeat).
    stack.runs.reserve(below.runs.size() + 1);
    stack.runs.push_back({1, 1});
    stack.runs.insert(stack.runs.end(), below.runs.begin(), below.runs.end());
  }
}

MultilayerResponse LayeredFilm::at(int k, float cosIncidence) const {
  const float c = std::clamp(cosIncidence, 1e-4f, 1.0f);
  return multilayerResponse(stacks_[k], std::acos(double(c)), lambdas_[k]);
}

FreeStandingFilm::Reflectance LayeredFilm::reflectance(float cosIncidence) const {
  FreeStandingFilm::Reflectance r;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const MultilayerResponse m = at(k, cosIncidence);
    r.s[k] = float(m.rs);
    r.p[k] = float(m.rp);
  }
  return r;
}

Spectrum LayeredFilm::transmittanceProduct(float cos1, float cos2) const {
  Spectrum t;
  for (int k = 0; k < kSpectrumSamples; ++k) {
    const MultilayerResponse a = at(k, cos1), b = at(k, cos2);
    t[k] = float(0.5 * (a.ts * b.ts + a.tp * b.tp));
  }
  return t;
}

Spectrum LayeredFilm::weightedTransmittanceProducts(FloatLanes weight, FloatLanes cos1, FloatLanes cos2) const {
  Spectrum sum;
  for (int j = 0; j < kLaneCount; ++j)
    if (weight[j] != 0.0f) sum += weight[j] * transmittanceProduct(cos1[j], cos2[j]);
  return sum;
}

FreeStandingFilm::Averages LayeredFilm::averagesOverWavelengths(FloatLanes cosIncidence,
                                                                const Spectrum& transmittanceWeight) const {
  FreeStandingFilm::Averages sum{};
  for (int j = 0; j < kLaneCount; ++j)
    for (int k = 0; k < kSpectrumSamples; ++k) {
      const MultilayerResponse m = at(k, cosIncidence[j]);
      sum.reflectance[j] += float(m.reflectance());
      sum.weightedTransmittanceSqr[j] += transmittanceWeight[k] * float(0.5 * (m.ts * m.ts + m.tp * m.tp));
    }
  const float mean = 1.0f / float(kSpectrumSamples);
  return {sum.reflectance * mean, sum.weightedTransmittanceSqr * mean};
}

}  // namespace columba
