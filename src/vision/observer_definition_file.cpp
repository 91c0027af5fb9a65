#include "vision/observer_definition_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/number_text.h"
#include "core/table_rows.h"

namespace columba {

namespace {

bool notApplicable(const std::string& cell) { return cell == "NA" || cell == "-"; }

// One row's cells by column name.
struct Row {
  const std::vector<std::string>& header;
  const std::vector<std::string>& values;
  const std::string& path;
  int line;

  std::optional<std::string> text(const std::string& column) const {
    const auto at = std::find(header.begin(), header.end(), column);
    if (at == header.end()) return std::nullopt;
    const std::string& v = values[size_t(at - header.begin())];
    if (notApplicable(v)) return std::nullopt;
    return v;
  }
  // The number in `column` within [lo, hi], or nothing where the column is absent or NA.
  std::optional<double> number(const std::string& column, double lo, double hi) const {
    const std::optional<std::string> t = text(column);
    if (!t) return std::nullopt;
    const std::optional<double> v = parseNumber<double>(*t);
    if (!v) throw InputError({path, line}, "column '" + column + "': '" + *t + "' is not a number (NA where none)");
    if (!(*v >= lo && *v <= hi))
      throw InputError({path, line}, fmt::format("column '{}': {} lies outside [{:g}, {:g}]", column, *t, lo, hi));
    return v;
  }
};

const std::vector<std::string> kColumns = {"cone",       "lambda_max", "droplet", "lambda_cut",
                                           "lambda_mid", "density",    "weber",   "beta"};
const std::vector<std::string> kCones = {"UVS", "VS", "SWS", "MWS", "LWS", "DBL"};

}  // namespace

bool isObserverDefinitionHeader(const std::string& firstColumn) { return firstColumn == "cone"; }

ObserverDefinition readObserverDefinition(std::istream& in, const std::string& path, const std::string& name) {
  static const std::map<std::string, double> kDensity = {{"UVS", 1}, {"VS", 1}, {"SWS", 2}, {"MWS", 2}, {"LWS", 4}};
  ObserverDefinition d;
  d.name = name;
  d.description = "defined in " + path;
  std::vector<std::string> header;
  int headerLine = 0;
  // The cones as read, in the file's order, then sorted by name's place in kCones.
  struct Read {
    ConeClass cone;
    std::optional<double> density, weber;
    int line;
  };
  std::vector<Read> chromatic;
  std::optional<double> achromaticWeber;
  TableRows rows(in, TableRows::Separators::CommasOrWhiteSpace);
  for (std::vector<std::string> values; rows.next(values);) {
    const int lineNumber = rows.line();
    if (lineNumber > 1000) throw InputError({path, lineNumber}, "more than 1000 lines: a definition has a row a cone");
    if (header.empty()) {
      header = values;
      headerLine = lineNumber;
      for (const std::string& column : header)
        if (std::find(kColumns.begin(), kColumns.end(), column) == kColumns.end())
          throw InputError({path, lineNumber}, "column '" + column +
                                                   "' is not one of cone, lambda_max, droplet, lambda_cut, "
                                                   "lambda_mid, density, weber, beta");
      for (const char* needed : {"cone", "lambda_max", "droplet"})
        if (std::find(header.begin(), header.end(), needed) == header.end())
          throw InputError({path, lineNumber}, std::string("the header has no column '") + needed + "'");
      for (size_t c = 0; c < header.size(); ++c)
        if (std::find(header.begin(), header.begin() + long(c), header[c]) != header.begin() + long(c))
          throw InputError({path, lineNumber}, "column '" + header[c] + "' is given twice");
      continue;
    }
    if (values.size() != header.size())
      throw InputError({path, lineNumber}, "a row of " + std::to_string(values.size()) + " values under a header of " +
                                               std::to_string(header.size()) + " columns (NA where a value is none)");
    const Row row{header, values, path, lineNumber};
    const std::string cone = row.text("cone").value_or("NA");
    if (std::find(kCones.begin(), kCones.end(), cone) == kCones.end())
      throw InputError({path, lineNumber}, "cone '" + cone + "' is not one of UVS, VS, SWS, MWS, LWS, DBL");
    for (const Read& r : chromatic)
      if (r.cone.name == cone) throw InputError({path, lineNumber}, "cone '" + cone + "' is given twice");
    if (cone == "DBL" && d.doubleCone) throw InputError({path, lineNumber}, "cone 'DBL' is given twice");
    ConeClass c;
    c.name = cone;
    const std::optional<double> peak = row.number("lambda_max", 300.0, 700.0);
    if (!peak) throw InputError({path, lineNumber}, "cone '" + cone + "' needs its lambda_max (nm)");
    c.lambdaMaxNm = *peak;
    if (const std::optional<std::string> beta = row.text("beta")) {
      if (*beta != "yes" && *beta != "no")
        throw InputError({path, lineNumber}, "column 'beta': '" + *beta + "' is not yes or no");
      c.betaBand = *beta == "yes";
    }
    const std::optional<std::string> droplet = row.text("droplet");
    const std::optional<double> cut = row.number("lambda_cut", 300.0, 830.0),
                                mid = row.number("lambda_mid", 300.0, 900.0);
    if (droplet) {
      const std::optional<OilDropletType> type = parseOilDropletType(*droplet);
      if (!type) throw InputError({path, lineNumber}, "droplet '" + *droplet + "' is not one of T, C, Y, R, P (or NA)");
      if (*type != OilDropletType::T) {
        if (!cut) throw InputError({path, lineNumber}, "a " + *droplet + " droplet needs its lambda_cut (nm)");
        if (mid && !(*mid > *cut)) throw InputError({path, lineNumber}, "lambda_mid must lie above lambda_cut");
        c.droplet = mid ? oilDropletFromCutAndMid(*cut, *mid) : oilDropletOfType(*type, *cut);
      }
    }
    if ((!droplet || *droplet == "T") && (cut || mid))
      throw InputError({path, lineNumber}, "lambda_cut and lambda_mid belong to C, Y, R and P droplets: NA here");
    const std::optional<double> density = row.number("density", kLeastRelativeDensity, kMostRelativeDensity);
    const std::optional<double> weber = row.number("weber", kLeastWeberFraction, kMostWeberFraction);
    if (cone == "DBL") {
      if (density) throw InputError({path, lineNumber}, "the double cone has no density in the chromatic model: NA");
      d.doubleCone = c;
      achromaticWeber = weber;
      continue;
    }
    chromatic.push_back({c, density, weber, lineNumber});
  }
  if (header.empty()) throw InputError({path, rows.line()}, "no header row (cone, lambda_max, droplet, ...)");
  std::sort(chromatic.begin(), chromatic.end(), [](const Read& a, const Read& b) {
    return std::find(kCones.begin(), kCones.end(), a.cone.name) < std::find(kCones.begin(), kCones.end(), b.cone.name);
  });
  if (chromatic.size() < 2) throw InputError({path, headerLine}, "fewer than two chromatic cones (besides DBL)");
  if (chromatic.front().cone.name == "UVS" && chromatic.size() > 1 && chromatic[1].cone.name == "VS")
    throw InputError({path, chromatic[1].line}, "a bird has a UVS or a VS cone, not both");
  d.noise.weberFraction = 0.1;
  d.noise.weberReference = chromatic.size() - 1;
  d.noise.achromaticWeberFraction = achromaticWeber.value_or(0.1);
  bool weberGiven = false;
  for (size_t i = 0; i < chromatic.size(); ++i) {
    const Read& r = chromatic[i];
    d.cones.push_back(r.cone);
    d.noise.relativeDensities.push_back(r.density.value_or(kDensity.at(r.cone.name)));
    if (r.weber) {
      if (weberGiven)
        throw InputError({path, r.line},
                         "a Weber fraction on a second chromatic cone: give it for one (the reference)");
      weberGiven = true;
      d.noise.weberFraction = *r.weber;
      d.noise.weberReference = i;
    }
  }
  return d;
}

}  // namespace columba
