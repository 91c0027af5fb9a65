#include "fit/spectra_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>

#include "core/error.h"
#include "core/number_text.h"
#include "core/spectrum.h"
#include "core/table_rows.h"

namespace columba {

namespace {

float number(const std::string& path, int line, const std::string& what, const std::string& text) {
  const std::optional<float> v = parseNumber<float>(text);
  if (!v) throw InputError({path, line}, fmt::format("{} '{}' is not a number", what, text));
  return *v;
}

void checkSample(const std::string& path, int line, const SpectraSample& s) {
  if (s.wavelength < kSpectralMin || s.wavelength > kLambdaMax)
    throw InputError({path, line}, fmt::format("wavelength_nm {} lies outside {:g}..{:g} nm", s.wavelength,
                                               kSpectralMin, kLambdaMax));
  if (s.thetaI < 0.0f || s.thetaI >= 90.0f || s.thetaO < 0.0f || s.thetaO >= 90.0f)
    throw InputError({path, line},
                     fmt::format("theta_i {} and theta_o {} must lie in [0, 90) degrees", s.thetaI, s.thetaO));
}

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// One spectrum column of a wide table and the directions of its samples.
struct SpectrumColumn {
  size_t index;
  float thetaI, phiI, thetaO, phiO;
};

std::vector<SpectrumColumn> spectrumColumns(const std::string& path, int line, const std::vector<std::string>& header,
                                            size_t wavelengthColumn, const SpectraGeometry& geometry) {
  std::vector<size_t> plain;
  std::vector<SpectrumColumn> columns;
  for (size_t k = 0; k < header.size(); ++k) {
    if (k == wavelengthColumn) continue;
    const std::string& name = header[k];
    if (startsWith(name, "R_theta") || startsWith(name, "TRT_theta")) continue;  // parts of total_theta
    if (startsWith(name, "total_theta")) {
      const float theta = number(path, line, "the angle of column '" + name + "'", name.substr(11));
      columns.push_back({k, theta, geometry.phiI, theta, geometry.phiI + 180.0f});
    } else {
      plain.push_back(k);
    }
  }
  if (plain.empty()) return columns;
  if (geometry.thetaI.empty())
    throw InputError({path, line}, fmt::format("column '{}' is a spectrum without directions: give the light's "
                                               "angle (--theta-i, and --geometry mirror|normal)",
                                               header[plain.front()]));
  if (geometry.thetaI.size() != 1 && geometry.thetaI.size() != plain.size())
    throw InputError({path, line}, fmt::format("{} light angles for {} spectrum columns: give one, or one each",
                                               geometry.thetaI.size(), plain.size()));
  for (size_t j = 0; j < plain.size(); ++j) {
    const float theta = geometry.thetaI[geometry.thetaI.size() == 1 ? 0 : j];
    const bool mirror = geometry.view == SpectraGeometry::View::Mirror;
    columns.push_back({plain[j], theta, geometry.phiI, mirror ? theta : 0.0f, mirror ? geometry.phiI + 180.0f : 0.0f});
  }
  return columns;
}

}  // namespace

std::vector<SpectraSample> readSpectraCSV(const std::string& path, const SpectraGeometry& geometry) {
  std::ifstream in(path);
  if (!in) throw InputError({path, 0}, "cannot open the spectra file");
  static const std::array<const char*, 6> names = {"theta_i", "phi_i",         "theta_o",
                                                   "phi_o",   "wavelength_nm", "reflectance"};
  static const std::array<const char*, 5> wavelengthNames = {"wavelength_nm", "wavelength", "wl", "lambda", "nm"};
  std::optional<std::array<size_t, 6>> longColumns;  // the long layout's
  std::optional<size_t> wavelengthColumn;            // a wide layout's
  std::vector<SpectrumColumn> spectra;
  std::vector<SpectraSample> samples;
  std::vector<std::vector<SpectraSample>> wide;  // a wide layout's, by spectrum: each spectrum's wavelengths together
  bool warnedRetro = false;
  TableRows rows(in, TableRows::Separators::Commas);
  for (std::vector<std::string> fields; rows.next(fields);) {
    const int lineNo = rows.line();
    if (!longColumns && !wavelengthColumn) {
      std::array<size_t, 6> column{};
      bool all = true;
      for (size_t k = 0; k < names.size() && all; ++k) {
        auto it = std::find(fields.begin(), fields.end(), names[k]);
        all = it != fields.end();
        if (all) column[k] = size_t(it - fields.begin());
      }
      if (all) {
        longColumns = column;
        continue;
      }
      for (const char* name : wavelengthNames) {
        auto it = std::find(fields.begin(), fields.end(), name);
        if (it != fields.end() && !wavelengthColumn) wavelengthColumn = size_t(it - fields.begin());
      }
      if (!wavelengthColumn)
        throw InputError({path, lineNo},
                         "the header names neither the columns theta_i, phi_i, theta_o, phi_o, "
                         "wavelength_nm, reflectance nor a wavelength column (wavelength_nm, wl, ...) "
                         "with one column per spectrum");
      spectra = spectrumColumns(path, lineNo, fields, *wavelengthColumn, geometry);
      if (spectra.empty()) throw InputError({path, lineNo}, "the header names a wavelength column but no spectrum");
      wide.resize(spectra.size());
      continue;
    }
    auto field = [&](size_t k) { return k < fields.size() ? fields[k] : std::string(); };
    if (longColumns) {
      std::array<float, 6> v{};
      for (size_t k = 0; k < names.size(); ++k) v[k] = number(path, lineNo, names[k], field((*longColumns)[k]));
      SpectraSample s{v[0], v[1], v[2], v[3], v[4], v[5]};
      checkSample(path, lineNo, s);
      const float turn = std::fmod(std::abs(s.phiO - s.phiI), 360.0f);
      if (!warnedRetro && s.thetaI > 0.0f && s.thetaO == s.thetaI && turn == 0.0f) {
        warn({path, lineNo},
             "phi_o equals phi_i, so omega_o lies on the light's side (the retro direction); the mirror "
             "direction of a specular spectrum is phi_o = phi_i + 180");
        warnedRetro = true;
      }
      samples.push_back(s);
      continue;
    }
    const float lambda = number(path, lineNo, "the wavelength", field(*wavelengthColumn));
    for (size_t j = 0; j < spectra.size(); ++j) {
      const SpectrumColumn& c = spectra[j];
      SpectraSample s{c.thetaI, c.phiI, c.thetaO, c.phiO, lambda, 0.0f};
      s.reflectance = number(path, lineNo, "reflectance", field(c.index));
      checkSample(path, lineNo, s);
      wide[j].push_back(s);
    }
  }
  for (const std::vector<SpectraSample>& column : wide) samples.insert(samples.end(), column.begin(), column.end());
  if (samples.empty()) throw InputError({path, 0}, "the spectra file has no data rows");
  return samples;
}

}  // namespace columba
