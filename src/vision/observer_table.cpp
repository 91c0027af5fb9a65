#include "vision/observer_table.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/number_text.h"
#include "core/table_rows.h"
#include "vision/observer_definition_file.h"

namespace columba {

namespace {
constexpr std::uintmax_t kMostBytes = std::uintmax_t(16) << 20;
constexpr size_t kMostRows = 100000;

double number(const std::string& text, const std::string& path, int line, const std::string& column) {
  const std::optional<double> v = parseNumber<double>(text);
  if (!v) throw InputError({path, line}, "column '" + column + "': '" + text + "' is not a number");
  return *v;
}
}  // namespace

Observer readObserverTable(std::istream& table, const std::string& path, const std::string& name) {
  static const std::vector<std::string> kWavelength = {"wl", "wavelength", "wavelength_nm", "lambda"};
  static const std::vector<std::string> kCones = {"UVS", "VS", "SWS", "MWS", "LWS", "DBL"};
  static const std::map<std::string, double> kDensity = {{"UVS", 1}, {"VS", 1}, {"SWS", 2}, {"MWS", 2}, {"LWS", 4}};
  std::vector<std::string> header;
  int headerLine = 0;
  std::vector<double> wavelengths;
  std::vector<std::vector<double>> columns;
  TableRows rows(table, TableRows::Separators::CommasOrWhiteSpace);
  for (std::vector<std::string> row; rows.next(row);) {
    const int lineNumber = rows.line();
    if (header.empty()) {
      header = row;
      headerLine = lineNumber;
      if (std::find(kWavelength.begin(), kWavelength.end(), header.front()) == kWavelength.end())
        throw InputError({path, lineNumber},
                         "the first column is '" + header.front() +
                             "', not a wavelength column (wl, wavelength, wavelength_nm or lambda)");
      for (size_t c = 1; c < header.size(); ++c) {
        if (std::find(kCones.begin(), kCones.end(), header[c]) == kCones.end())
          throw InputError({path, lineNumber},
                           "column '" + header[c] + "' is not a cone: name the columns UVS or VS, SWS, MWS, LWS, DBL");
        if (std::find(header.begin() + 1, header.begin() + long(c), header[c]) != header.begin() + long(c))
          throw InputError({path, lineNumber}, "column '" + header[c] + "' is given twice");
      }
      columns.resize(header.size() - 1);
      continue;
    }
    if (row.size() != header.size())
      throw InputError({path, lineNumber}, "a row of " + std::to_string(row.size()) + " values under a header of " +
                                               std::to_string(header.size()) + " columns");
    if (wavelengths.size() == kMostRows)
      throw InputError({path, lineNumber}, "more than " + std::to_string(kMostRows) + " rows");
    const double wl = number(row[0], path, lineNumber, header[0]);
    if (!wavelengths.empty() && !(wl > wavelengths.back()))
      throw InputError({path, lineNumber}, "the wavelengths must increase (" + row[0] + " nm follows " +
                                               std::to_string(wavelengths.back()) + " nm)");
    wavelengths.push_back(wl);
    for (size_t c = 1; c < row.size(); ++c) {
      const double v = number(row[c], path, lineNumber, header[c]);
      if (v < 0.0) throw InputError({path, lineNumber}, "column '" + header[c] + "': a sensitivity is not negative");
      columns[c - 1].push_back(v);
    }
  }
  if (header.empty()) throw InputError({path, rows.line()}, "no header row (wl and the cones' names)");
  if (wavelengths.size() < 2) throw InputError({path, rows.line()}, "fewer than two rows of sensitivities");

  Observer o;
  o.name = name;
  o.grid = visionGrid();
  std::vector<double> densities;
  bool shortest = false;
  for (const std::string& cone : kCones) {
    const auto at = std::find(header.begin() + 1, header.end(), cone);
    if (at == header.end()) continue;
    // Divided by its largest value before it is summed, so that a curve in any unit, up to the
    // largest double, has an area without overflow (1e307 a row summed to inf, and every catch to NaN).
    std::vector<double> column = columns[size_t(at - header.begin()) - 1];
    const double largest = *std::max_element(column.begin(), column.end());
    if (largest > 0.0)
      for (double& v : column) v /= largest;
    std::vector<double> curve(o.grid.count);
    double area = 0.0;
    for (size_t i = 0; i < o.grid.count; ++i)
      area += curve[i] = interpolateTabulated(wavelengths, column, o.grid.wavelength(i));
    area *= o.grid.stepNm;
    if (!(area > 0.0))
      throw InputError({path, headerLine}, "column '" + cone + "' has no sensitivity between 300 and 830 nm");
    std::vector<float> sensitivity(o.grid.count);
    for (size_t i = 0; i < o.grid.count; ++i) sensitivity[i] = float(curve[i] / area);
    if (cone == "DBL") {
      o.achromaticChannel = cone;
      o.achromatic = std::move(sensitivity);
      continue;
    }
    if (cone == "UVS" || cone == "VS") {
      if (shortest) throw InputError({path, headerLine}, "a bird has a UVS or a VS cone, not both");
      shortest = true;
    }
    o.channels.push_back(cone);
    o.sensitivities.push_back(std::move(sensitivity));
    densities.push_back(kDensity.at(cone));
  }
  if (o.channels.size() < 2) throw InputError({path, headerLine}, "fewer than two chromatic cones (besides DBL)");
  o.noise = {densities, 0.1, densities.size() - 1, 0.1};
  return o;
}

bool namesObserverTable(const std::string& text) {
  return text.size() > 4 && text.compare(text.size() - 4, 4, ".csv") == 0;
}

Observer observerNamedOrTabulated(const std::string& nameOrPath) {
  if (namesObserverTable(nameOrPath)) return readObserverTableFile(nameOrPath);
  if (!isBuiltinObserver(nameOrPath))
    throw std::invalid_argument("unknown observer '" + nameOrPath + "' (known: " + builtinObserverNames() +
                                "; or a table of sensitivities or of cone parameters, FILE.csv)");
  return namedObserver(nameOrPath);
}

Observer readObserverTableFile(const std::string& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw InputError({path, 0}, "cannot read the observer table: " + ec.message());
  if (size > kMostBytes)
    throw InputError({path, 0}, "an observer table of " + std::to_string(size) + " bytes is larger than 16 MiB");
  std::ifstream file(path);
  if (!file) throw InputError({path, 0}, "cannot open the observer table");
  std::stringstream in;
  in << file.rdbuf();
  const std::string name = std::filesystem::path(path).stem().string();
  // A definition's header starts with `cone`; a table's with its wavelength column.
  std::vector<std::string> header;
  const bool definition = TableRows(in, TableRows::Separators::CommasOrWhiteSpace).next(header) &&
                          isObserverDefinitionHeader(header.front());
  in.clear();
  in.seekg(0);
  if (definition) return makeObserver(readObserverDefinition(in, path, name));
  return readObserverTable(in, path, name);
}

}  // namespace columba
