#include "fit/spectra_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "barbule/measurement.h"
#include "barbule/model.h"
#include "barbule/parameter_reader.h"
#include "core/byte_order_mark.h"
#include "core/error.h"
#include "core/math.h"
#include "scene/scene_variables.h"

namespace columba {

namespace {

bool sameDirections(const SpectraSample& a, const SpectraSample& b) {
  return a.thetaI == b.thetaI && a.phiI == b.phiI && a.thetaO == b.thetaO && a.phiO == b.phiO;
}

// The value the held parameters (a preset, -D values) give the parameter of that name, where it is
// one of the barbule's numbers.
std::optional<double> heldValue(const BarbuleParameters& p, const std::string& name) {
  const std::map<std::string, double> values = {{"b", p.b}, {"phi_0", p.phi0},    {"phi_1", p.phi1},    {"mu", p.mu},
                                                {"H", p.H}, {"height", p.height}, {"ext_ior", p.extIOR}};
  const auto it = values.find(name);
  return it == values.end() ? std::nullopt : std::optional<double>(it->second);
}

}  // namespace

std::vector<float> modelSpectra(const BarbuleParameters& parameters, const std::vector<SpectraSample>& samples,
                                const InstrumentAperture& aperture) {
  const BarbuleModel barbule(parameters);
  std::vector<float> model(samples.size());
  // Consecutive rows with the same directions share one evaluation per kSpectrumSamples wavelengths.
  for (size_t first = 0; first < samples.size();) {
    size_t count = 1;
    while (count < size_t(kSpectrumSamples) && first + count < samples.size() &&
           sameDirections(samples[first], samples[first + count]))
      ++count;
    const SpectraSample& s = samples[first];
    std::array<float, kSpectrumSamples> lambdas;
    for (size_t k = 0; k < lambdas.size(); ++k) lambdas[k] = samples[first + std::min(k, count - 1)].wavelength;
    const Vec3 wi = directionFromAngles(degToRad(s.thetaI), degToRad(s.phiI));
    const Vec3 wo = directionFromAngles(degToRad(s.thetaO), degToRad(s.phiO));
    const Wavelengths wl = Wavelengths::fixed(lambdas);
    if (aperture.isPoint()) {
      BarbuleLobes lobes = barbule.lobes(wi, wo, wl);
      for (size_t k = 0; k < count; ++k) model[first + k] = kPi * (lobes.reflection[int(k)] + lobes.trt[int(k)]);
    } else {
      // The average over the illumination and the collection cones.
      std::array<double, kSpectrumSamples> sum{};
      const std::vector<ConeDirection> ins = coneDirections(wi, aperture), outs = coneDirections(wo, aperture);
      for (const ConeDirection& in : ins)
        for (const ConeDirection& out : outs) {
          BarbuleLobes lobes = barbule.lobes(in.w, out.w, wl);
          for (size_t k = 0; k < count; ++k)
            sum[k] += in.weight * out.weight * double(lobes.reflection[int(k)] + lobes.trt[int(k)]);
        }
      for (size_t k = 0; k < count; ++k) model[first + k] = float(kPi * sum[k]);
    }
    first += count;
  }
  return model;
}

BarbuleParameters barbuleParametersWith(const std::map<std::string, double>& values,
                                        const std::map<std::string, std::string>& given,
                                        std::optional<BarbuleParameterProblem>* implausible) {
  Properties props;
  props.tag = "bsdf";
  props.type = "barbulebsdf";
  props.nameParameter = [](const std::string& name) { return "barbule parameter " + name; };
  // A value may stand as $name in a given text (a rod's diameter in `layers`), as in a scene file;
  // those values set no parameter of their own.
  std::map<std::string, std::string> asText;
  for (const auto& [name, value] : values) asText[name] = fmt::format("{:.9g}", value);
  const SceneVariables variables(asText);
  for (const auto& [name, text] : given)  // a number, a preset, a named index, layers
    props.setFromText(name, variables.substitute(text, {"barbule parameter " + name, 0}));
  const std::vector<std::string> unsubstituted = variables.unusedDefines();
  for (const auto& [name, value] : values)
    if (std::find(unsubstituted.begin(), unsubstituted.end(), name) != unsubstituted.end()) props.setFloat(name, value);
  std::optional<BarbuleParameterProblem> odd;
  BarbuleParameters p = readBarbuleParameters(props, odd);
  props.checkAllUsed();
  if (implausible) *implausible = odd;
  return p;
}

std::optional<std::string> implausibleScaleWarning(double scale) {
  if (scale >= 1.0 / 3.0 && scale <= 3.0) return std::nullopt;
  const double percent = scale > 1.0 ? scale / 100.0 : scale * 100.0;
  if (percent > 1.0 / 3.0 && percent < 3.0)
    return fmt::format(
        "the fit scaled the model by {:.3g}: the measured spectra are about 100 times {} than the "
        "model's reflectance factor, a fraction of a white standard's; percent against fractions?",
        scale, scale > 1.0 ? "larger" : "smaller");
  return fmt::format(
      "the fit scaled the model by {:.3g}, far from 1: the measured geometry may not be the model's (is "
      "omega_o the mirror direction, phi_o = phi_i + 180?), or the spectra are relative to another "
      "standard; the fitted values may not mean what they seem",
      scale);
}

SpectraFitResult fitSpectra(const SpectraFitSettings& settings) {
  std::vector<std::string> fixedNames;
  for (const auto& value : settings.fixed) fixedNames.push_back(value.first);
  checkFitSettings(settings.parameters, settings.fit, fixedNames);
  if (!(settings.aperture.halfAngleDeg >= 0.0f && settings.aperture.halfAngleDeg < 45.0f))
    throw std::invalid_argument(
        fmt::format("the aperture's half-angle must lie in [0, 45) degrees, not {:g}", settings.aperture.halfAngleDeg));
  // A bad -D is refused before the first evaluation, with the varied parameters at their lower
  // bounds; a bound the model takes but no barbule has (a thickness in nm where um is meant) too.
  std::map<std::string, double> lowest;
  for (const FitParameter& p : settings.parameters) lowest[p.name] = p.lower;
  barbuleParametersWith(lowest, settings.fixed);
  for (const FitParameter& p : settings.parameters)
    for (double bound : {p.lower, p.upper}) {
      std::map<std::string, std::string> others = settings.fixed;
      others.erase(p.name);
      std::map<std::string, double> at = lowest;
      at[p.name] = bound;
      std::optional<BarbuleParameterProblem> odd;
      barbuleParametersWith(at, others, &odd);
      if (odd && odd->parameter == p.name)
        throw std::invalid_argument(fmt::format("{}={:g}:{:g}: {}", p.name, p.lower, p.upper, odd->message));
    }
  // A preset is the starting point of the parameters it sets whose start was not given (where its
  // value lies within their bounds).
  std::vector<FitParameter> parameters = settings.parameters;
  if (settings.fixed.count("preset") > 0) {
    const BarbuleParameters held = barbuleParametersWith({}, settings.fixed);
    for (FitParameter& p : parameters)
      if (const std::optional<double> v = heldValue(held, p.name); !p.start && v && *v >= p.lower && *v <= p.upper)
        p.start = *v;
  }
  std::vector<float> target;
  for (const SpectraSample& s : settings.samples) target.push_back(s.reflectance);
  ScaledLoss loss(std::move(target), {}, settings.loss, settings.scale);
  auto parametersAt = [&](const std::vector<double>& values) {
    std::map<std::string, double> named;
    for (size_t i = 0; i < values.size(); ++i) named[parameters[i].name] = values[i];
    return barbuleParametersWith(named, settings.fixed);
  };
  SpectraFitResult result;
  result.fit = runFit(
      parameters,
      [&](const std::vector<double>& values) {
        return loss(modelSpectra(parametersAt(values), settings.samples, settings.aperture));
      },
      settings.fit);
  result.model = modelSpectra(parametersAt(result.fit.values), settings.samples, settings.aperture);
  return result;
}

}  // namespace columba
