#include "vision/observer_response.h"

#include <cmath>
#include <stdexcept>

#include "core/illuminant.h"

namespace columba {

namespace {
// Channel c's sensitivity: the chromatic ones in order, then the achromatic one.
const std::vector<float>& channelCurve(const Observer& o, size_t c) {
  return c < o.sensitivities.size() ? o.sensitivities[c] : o.achromatic;
}

WavelengthTable observerWavelengths(const Observer& o, size_t channels) {
  const SpectralGrid& g = o.grid;
  if (g.stepNm != 1.0 || g.firstNm != std::floor(g.firstNm))
    throw std::invalid_argument("observer '" + o.name + "': rendering needs sensitivities at whole nanometres");
  const double uniform = 1.0 / (g.lastNm() - g.firstNm);
  std::vector<double> density(g.count);
  for (size_t i = 0; i < g.count; ++i) {
    double mean = 0.0;
    for (size_t c = 0; c < channels; ++c) mean += channelCurve(o, c)[i];
    density[i] = 0.9 * mean / double(channels) + 0.1 * uniform;
  }
  return makeWavelengthTable(float(g.firstNm), density);
}

std::vector<std::string> channelNames(const Observer& o) {
  std::vector<std::string> names = o.channels;
  if (o.hasAchromatic()) names.push_back(o.achromaticChannel);
  return names;
}
}  // namespace

Adaptation adaptationNamed(const std::string& name) {
  if (name == "d65") return Adaptation::D65;
  if (name == "none") return Adaptation::None;
  throw std::invalid_argument("unknown adaptation '" + name + "' (known: d65, none)");
}

std::string describeObserver(const ObserverResponse& response) {
  std::string channels;
  for (const std::string& c : response.channels()) channels += (channels.empty() ? "" : ", ") + c;
  const std::string shortest = response.channels().empty() ? "S" : response.channels().front();
  return response.observer().name + ": quantum catches of " + channels +
         (response.adaptation() == Adaptation::D65 ? ", each relative to a white reflector's under D65 (von Kries)"
                                                   : ", absolute (per unit radiance; no adaptation)") +
         "; the PNG shows red (2 LWS + " + shortest + ") / 3, green MWS, blue (2 SWS + " + shortest + ") / 3";
}

ObserverResponse::ObserverResponse(Observer observer, Adaptation adaptation)
    : observer_(std::move(observer)),
      adaptation_(adaptation),
      channels_(channelNames(observer_)),
      wavelengths_(observerWavelengths(observer_, channels_.size())) {
  const SpectralGrid& g = observer_.grid;
  for (size_t c = 0; c < channels_.size(); ++c) {
    const std::vector<float>& curve = channelCurve(observer_, c);
    double white = 1.0;
    if (adaptation_ == Adaptation::D65) {
      white = 0.0;
      for (size_t i = 0; i < g.count; ++i) white += double(d65(float(g.wavelength(i)))) * curve[i] * g.stepNm;
    }
    white_.push_back(white);
  }
}

float ObserverResponse::sensitivity(size_t c, float lambda) const {
  const SpectralGrid& g = observer_.grid;
  const double x = (double(lambda) - g.firstNm) / g.stepNm;
  if (!(x >= 0.0) || x > double(g.count - 1)) return 0.0f;
  const size_t i = std::min(size_t(x), g.count - 2);
  const double f = x - double(i);
  const std::vector<float>& s = channelCurve(observer_, c);
  return float((1.0 - f) * s[i] + f * s[i + 1]);
}

void ObserverResponse::accumulate(const Spectrum& L, const Wavelengths& wl, float scale, float* values) const {
  for (size_t c = 0; c < channels_.size(); ++c) {
    double sum = 0.0;
    for (int k = 0; k < kSpectrumSamples; ++k)
      if (wl.pdf[k] > 0.0f) sum += double(L[k]) * sensitivity(c, wl[k]) / double(wl.pdf[k]);
    values[c] += float(sum * scale / (kSpectrumSamples * white_[c]));
  }
}

}  // namespace columba
