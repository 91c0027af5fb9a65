#include "fit/spectra_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "barbule/measurement.h"
#include "barbule/parameter_reader.h"
#include "core/byte_order_mark.h"
#include "core/error.h"
#include "core/math.h"

namespace columba {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) {
    size_t first = field.find_first_not_of(" \t\r"), last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
  }
  return fields;
}

bool sameDirections(const SpectraSample& a, const SpectraSample& b) {
  return a.thetaI == b.thetaI && a.phiI == b.phiI && a.thetaO == b.thetaO && a.phiO == b.phiO;
}

}  // namespace

std::vector<SpectraSample> readSpectraCSV(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path, 0}, "cannot open the spectra file");
  skipByteOrderMark(in);
  static const std::array<const char*, 6> names = {"theta_i", "phi_i",         "theta_o",
                                                   "phi_o",   "wavelength_nm", "reflectance"};
  std::array<size_t, 6> column{};
  bool haveHeader = false;
  std::vector<SpectraSample> samples;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
    std::vector<std::string> fields = splitFields(line);
    if (!haveHeader) {
      for (size_t k = 0; k < names.size(); ++k) {
        auto it = std::find(fields.begin(), fields.end(), names[k]);
        if (it == fields.end())
          throw InputError({path, lineNo}, fmt::format("the header has no column '{}' (it needs theta_i, phi_i, "
                                                       "theta_o, phi_o, wavelength_nm, reflectance)",
                                                       names[k]));
        column[k] = size_t(it - fields.begin());
      }
      haveHeader = true;
      continue;
    }
    std::array<float, 6> v{};
    for (size_t k = 0; k < names.size(); ++k) {
      const std::string text = column[k] < fields.size() ? fields[column[k]] : "";
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v[k]);
      if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v[k]))
        throw InputError({path, lineNo}, fmt::format("{} '{}' is not a number", names[k], text));
    }
    if (v[4] < 360.0f || v[4] > 830.0f)
      throw InputError({path, lineNo}, fmt::format("wavelength_nm {} lies outside 360..830 nm", v[4]));
    if (v[0] < 0.0f || v[0] >= 90.0f || v[2] < 0.0f || v[2] >= 90.0f)
      throw InputError({path, lineNo},
                       fmt::format("theta_i {} and theta_o {} must lie in [0, 90) degrees", v[0], v[2]));
    samples.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
  }
  if (samples.empty()) throw InputError({path, 0}, "the spectra file has no data rows");
  return samples;
}

std::vector<float> modelSpectra(const BarbuleParameters& parameters, const std::vector<SpectraSample>& samples) {
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
    BarbuleLobes lobes = barbule.lobes(wi, wo, Wavelengths::fixed(lambdas));
    for (size_t k = 0; k < count; ++k) model[first + k] = kPi * (lobes.reflection[int(k)] + lobes.trt[int(k)]);
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
  for (const auto& [name, text] : given) {
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size())
      props.setFloat(name, number);
    else
      props.setString(name, text);  // a preset, a named index
  }
  for (const auto& [name, value] : values) props.setFloat(name, value);
  std::optional<BarbuleParameterProblem> odd;
  BarbuleParameters p = readBarbuleParameters(props, odd);
  props.checkAllUsed();
  if (implausible) *implausible = odd;
  return p;
}

SpectraFitResult fitSpectra(const SpectraFitSettings& settings) {
  std::vector<std::string> fixedNames;
  for (const auto& value : settings.fixed) fixedNames.push_back(value.first);
  checkFitSettings(settings.parameters, settings.fit, fixedNames);
  barbuleParametersWith({}, settings.fixed);  // refuses a bad -D before the first evaluation
  // A bound the model takes but no barbule has (a thickness in nm where um is meant) is refused
  // before any evaluation too.
  for (const FitParameter& p : settings.parameters)
    for (double bound : {p.lower, p.upper}) {
      std::map<std::string, std::string> others = settings.fixed;
      others.erase(p.name);
      std::optional<BarbuleParameterProblem> odd;
      barbuleParametersWith({{p.name, bound}}, others, &odd);
      if (odd && odd->parameter == p.name)
        throw std::invalid_argument(fmt::format("{}={:g}:{:g}: {}", p.name, p.lower, p.upper, odd->message));
    }
  std::vector<float> target;
  for (const SpectraSample& s : settings.samples) target.push_back(s.reflectance);
  ScaledLoss loss(std::move(target), {}, settings.loss, settings.scale);
  auto parametersAt = [&](const std::vector<double>& values) {
    std::map<std::string, double> named;
    for (size_t i = 0; i < values.size(); ++i) named[settings.parameters[i].name] = values[i];
    return barbuleParametersWith(named, settings.fixed);
  };
  SpectraFitResult result;
  result.fit = runFit(
      settings.parameters,
      [&](const std::vector<double>& values) { return loss(modelSpectra(parametersAt(values), settings.samples)); },
      settings.fit);
  result.model = modelSpectra(parametersAt(result.fit.values), settings.samples);
  return result;
}

}  // namespace columba
