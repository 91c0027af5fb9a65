#include "vision/observer.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "vision/endler_mielke_table.h"
#include "vision/visual_pigment.h"

namespace columba {

std::vector<float> coneSensitivity(const SpectralGrid& grid, const ConeClass& cone) {
  std::vector<float> pigment = visualPigmentAbsorbance(grid, cone.lambdaMaxNm, cone.betaBand);
  std::vector<double> s(grid.count);
  double area = 0.0;
  for (std::size_t i = 0; i < grid.count; ++i) {
    double t = cone.droplet ? oilDropletTransmission(*cone.droplet, grid.wavelength(i)) : 1.0;
    s[i] = double(pigment[i]) * t;
    area += s[i];
  }
  area *= grid.stepNm;
  std::vector<float> out(grid.count);
  for (std::size_t i = 0; i < grid.count; ++i) out[i] = float(s[i] / area);
  return out;
}

void checkReceptorNoise(const ReceptorNoise& noise) {
  const std::vector<double>& eta = noise.relativeDensities;
  for (size_t i = 0; i < eta.size(); ++i)
    if (!(eta[i] >= kLeastRelativeDensity && eta[i] <= kMostRelativeDensity))
      throw std::invalid_argument(
          fmt::format("densities[{}] (a cone's relative density) {:g} lies outside [{:g}, {:g}]", i, eta[i],
                      kLeastRelativeDensity, kMostRelativeDensity));
  if (noise.weberReference >= eta.size())
    throw std::invalid_argument(fmt::format("weber_cone {} names no cone: give 0 to {}", noise.weberReference,
                                            eta.empty() ? 0 : eta.size() - 1));
  auto checkFraction = [](double w, const char* what) {
    if (!(w >= kLeastWeberFraction && w <= kMostWeberFraction))
      throw std::invalid_argument(
          fmt::format("{} {:g} lies outside [{:g}, {:g}]", what, w, kLeastWeberFraction, kMostWeberFraction));
  };
  checkFraction(noise.weberFraction, "weber (the reference cone's Weber fraction)");
  checkFraction(noise.achromaticWeberFraction, "the achromatic Weber fraction");
}

Observer makeObserver(const ObserverDefinition& definition, const SpectralGrid& grid) {
  if (definition.cones.size() < 2)
    throw std::invalid_argument("observer '" + definition.name + "' needs at least two chromatic cone classes");
  const ReceptorNoise& noise = definition.noise;
  if (noise.relativeDensities.size() != definition.cones.size())
    throw std::invalid_argument("observer '" + definition.name + "' has " + std::to_string(definition.cones.size()) +
                                " cones but " + std::to_string(noise.relativeDensities.size()) + " relative densities");
  try {
    checkReceptorNoise(noise);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("observer '" + definition.name + "': " + e.what());
  }
  Observer observer;
  observer.name = definition.name;
  observer.grid = grid;
  observer.noise = noise;
  for (const ConeClass& cone : definition.cones) {
    observer.channels.push_back(cone.name);
    observer.sensitivities.push_back(coneSensitivity(grid, cone));
  }
  if (definition.doubleCone) {
    observer.achromaticChannel = definition.doubleCone->name;
    observer.achromatic = coneSensitivity(grid, *definition.doubleCone);
  }
  return observer;
}

namespace {

// pavo's coldist defaults, used where a species' own values were not found: relative densities
// 1:2:2:4 (UVS/VS : SWS : MWS : LWS) of the Pekin robin Leiothrix lutea, and a Weber fraction of 0.1
// for its LWS cone (the fourth); 0.1 for the achromatic channel (pavo's weber.achro).
ReceptorNoise pavoDefaultNoise() { return {{1.0, 2.0, 2.0, 4.0}, 0.1, 3, 0.1}; }

std::vector<ObserverDefinition> makeBuiltins() {
  std::vector<ObserverDefinition> builtins;

  // The blue tit, Cyanistes (Parus) caeruleus, an ultraviolet-sensitive passerine. Pigment peaks
  // 371, 448, 502, 563 nm and oil-droplet cut-offs 330 (T), 413 (C), 507 (Y), 572 (R) nm from the
  // microspectrophotometry of Hart, Partridge, Cuthill & Bennett (2000, J Comp Physiol A 186:375-387),
  // as pavo's sensmodel documentation states them for this bird (its example "Blue tit visual system
  // based on Hart et al (2000)", with the beta band left out). The mid-points follow from the cut-offs
  // by Hart & Vorobyev's (2005) regressions for each droplet type (oil_droplet.h); the T droplet
  // filters nothing. No double cone: its droplet's parameters were not found in a source to hand.
  {
    ObserverDefinition d;
    d.name = "bluetit";
    d.description = "blue tit (Cyanistes caeruleus), ultraviolet-sensitive";
    d.cones = {
        {"UVS", 371.0, oilDropletOfType(OilDropletType::T, 330.0), false},
        {"SWS", 448.0, oilDropletOfType(OilDropletType::C, 413.0), false},
        {"MWS", 502.0, oilDropletOfType(OilDropletType::Y, 507.0), false},
        {"LWS", 563.0, oilDropletOfType(OilDropletType::R, 572.0), false},
    };
    d.noise = pavoDefaultNoise();
    builtins.push_back(d);
  }
  return builtins;
}

}  // namespace

const std::vector<ObserverDefinition>& builtinObserverDefinitions() {
  static const std::vector<ObserverDefinition> builtins = makeBuiltins();
  return builtins;
}

const ObserverDefinition* findObserverDefinition(const std::string& name) {
  for (const ObserverDefinition& d : builtinObserverDefinitions())
    if (d.name == name) return &d;
  return nullptr;
}

namespace {
// pavo's avg.uv and avg.v, read once from the compiled-in table.
const std::vector<Observer>& endlerMielkeObservers() {
  static const std::vector<Observer> observers = [] {
    std::istringstream table(kEndlerMielkeTable);
    return readEndlerMielkeObservers(table);
  }();
  return observers;
}

const Observer* findTabulatedObserver(const std::string& name) {
  for (const Observer& o : endlerMielkeObservers())
    if (o.name == name) return &o;
  return nullptr;
}

Observer onGrid(const Observer& tabulated, const SpectralGrid& grid) {
  std::vector<double> x(tabulated.grid.count);
  for (size_t i = 0; i < x.size(); ++i) x[i] = tabulated.grid.wavelength(i);
  Observer o = tabulated;
  o.grid = grid;
  for (std::vector<float>& s : o.sensitivities) {
    const std::vector<double> y(s.begin(), s.end());
    s = tabulateOnGrid(grid, [&](double l) { return interpolateTabulated(x, y, l); });
  }
  return o;
}
}  // namespace

std::vector<std::pair<std::string, std::string>> builtinObservers() {
  std::vector<std::pair<std::string, std::string>> list;
  for (const ObserverDefinition& d : builtinObserverDefinitions()) list.emplace_back(d.name, d.description);
  list.emplace_back("avg.uv", "average ultraviolet-sensitive bird (Endler & Mielke 2005; pavo's avg.uv)");
  list.emplace_back("avg.v", "average violet-sensitive bird (Endler & Mielke 2005; pavo's avg.v)");
  return list;
}

bool isBuiltinObserver(const std::string& name) {
  return findObserverDefinition(name) != nullptr || findTabulatedObserver(name) != nullptr;
}

std::string builtinObserverNames() {
  std::string known;
  for (const auto& [name, description] : builtinObservers()) known += (known.empty() ? "" : ", ") + name;
  return known;
}

Observer namedObserver(const std::string& name, const SpectralGrid& grid) {
  if (const ObserverDefinition* d = findObserverDefinition(name)) return makeObserver(*d, grid);
  if (const Observer* o = findTabulatedObserver(name)) return onGrid(*o, grid);
  throw std::invalid_argument("unknown observer '" + name + "' (known: " + builtinObserverNames() + ")");
}

std::vector<Observer> readEndlerMielkeObservers(std::istream& table) {
  std::vector<double> wavelengths;
  std::vector<std::vector<float>> columns(8);
  std::string line;
  int lineNumber = 0;
  while (std::getline(table, line)) {
    ++lineNumber;
    if (lineNumber <= 3 || line.find_first_not_of(" \t\r") == std::string::npos) continue;  // the header
    std::istringstream row(line);
    double wl = 0.0;
    if (!(row >> wl))
      throw std::invalid_argument("Endler & Mielke table, line " + std::to_string(lineNumber) + ": no wavelength");
    for (std::vector<float>& column : columns) {
      double v = 0.0;
      if (!(row >> v))
        throw std::invalid_argument("Endler & Mielke table, line " + std::to_string(lineNumber) +
                                    ": fewer than 8 sensitivities");
      column.push_back(float(v / 100.0));
    }
    wavelengths.push_back(wl);
  }
  if (wavelengths.size() < 2) throw std::invalid_argument("Endler & Mielke table: fewer than two rows");
  double step = wavelengths[1] - wavelengths[0];
  for (std::size_t i = 1; i < wavelengths.size(); ++i)
    if (std::abs(wavelengths[i] - wavelengths[0] - step * double(i)) > 1e-6)
      throw std::invalid_argument("Endler & Mielke table: wavelengths are not evenly spaced");
  SpectralGrid grid{wavelengths[0], step, wavelengths.size()};

  std::vector<Observer> observers(2);
  const char* names[2] = {"avg.uv", "avg.v"};
  const char* shortest[2] = {"UVS", "VS"};
  for (int k = 0; k < 2; ++k) {
    Observer& o = observers[k];
    o.name = names[k];
    o.grid = grid;
    o.channels = {shortest[k], "SWS", "MWS", "LWS"};
    for (int c = 0; c < 4; ++c) o.sensitivities.push_back(columns[4 * k + c]);
    o.noise = pavoDefaultNoise();
  }
  return observers;
}

}  // namespace columba
