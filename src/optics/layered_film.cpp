#include "optics/layered_film.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

#include "core/number_text.h"
#include "optics/melanin_index.h"

namespace columba {

namespace {
std::string trimmed(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// "N+Ki" as (N, K); nullopt where `text` is not of that form.
std::optional<std::pair<float, float>> complexIndex(const std::string& text) {
  if (text.size() < 4 || text.back() != 'i') return std::nullopt;
  const size_t plus = text.find('+', 1);
  if (plus == std::string::npos) return std::nullopt;
  const std::optional<float> n = parseNumber<float>(text.substr(0, plus));
  const std::optional<float> k = parseNumber<float>(text.substr(plus + 1, text.size() - plus - 2));
  if (!n || !k) return std::nullopt;
  return std::pair{*n, *k};
}
}  // namespace

FilmLayer melaninLayer(float thicknessUm) {
  FilmLayer layer;
  layer.n = RefractiveIndex::cauchy(MelaninIndex::kCauchyA, MelaninIndex::kCauchyB);
  layer.k = MelaninIndex::kExtinction;
  layer.kDecayNm = MelaninIndex::kExtinctionDecay;
  layer.thicknessUm = thicknessUm;
  return layer;
}

std::vector<FilmLayer> parseFilmLayers(const std::string& text) {
  std::vector<FilmLayer> layers;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = text.find(',', start);
    const std::string piece =
        trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    start = comma == std::string::npos ? text.size() + 1 : comma + 1;
    if (piece.empty() && comma == std::string::npos && !layers.empty()) break;
    const size_t colon = piece.rfind(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("layer '" + piece + "': give INDEX:THICKNESS (thickness in um)");
    const std::string index = trimmed(piece.substr(0, colon));
    const std::optional<float> thickness = parseNumber<float>(trimmed(piece.substr(colon + 1)));
    if (!thickness || !(*thickness >= 0.0f))
      throw std::invalid_argument("layer '" + piece + "': the thickness must be a number of micrometres, not negative");
    FilmLayer layer;
    layer.thicknessUm = *thickness;
    if (const std::optional<std::pair<float, float>> c = complexIndex(index)) {
      if (!(c->first > 0.0f) || !(c->second >= 0.0f))
        throw std::invalid_argument("layer '" + piece + "': an index N+Ki needs N > 0 and K >= 0");
      layer.n = RefractiveIndex::constant(c->first);
      layer.k = c->second;
    } else if (index == "melanin") {
      layer = melaninLayer(*thickness);
    } else if (const std::optional<RefractiveIndex> n = iorFromName(index)) {
      layer.n = *n;
    } else {
      throw std::invalid_argument("layer '" + piece + "': unknown index '" + index +
                                  "' (a number, a named index such as air, keratin, melanin, or N+Ki)");
    }
    layers.push_back(layer);
  }
  return layers;
}

LayeredFilm::LayeredFilm(const RefractiveIndex& cortex, float nOutside, float cortexThicknessUm,
                         const std::vector<FilmLayer>& below, const Wavelengths& wl) {
  for (int k = 0; k < kSpectrumSamples; ++k) {
    lambdas_[k] = wl[k];
    LayerStack& stack = stacks_[k];
    stack.incidentIndex = nOutside;
    stack.substrateIndex = nOutside;
    stack.layers.reserve(below.size() + 1);  // one allocation a wavelength, at every hit
    stack.layers.push_back({cortex(wl[k]), cortexThicknessUm});
    for (const FilmLayer& layer : below)
      stack.layers.push_back({std::complex<double>(layer.n(wl[k]), layer.extinction(wl[k])), layer.thicknessUm});
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
