#pragma once
// Named visual systems: the spectral sensitivities of a set of cone classes, with the receptor
// densities and Weber fraction the receptor-noise-limited model needs (docs/vision.md).
#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vision/oil_droplet.h"
#include "vision/spectral_grid.h"

namespace columba {

// One cone class built from published data: its pigment's peak wavelength (Govardovskii A1 template)
// and the oil droplet in front of it (none for a transparent droplet).
struct ConeClass {
  std::string name;  // the channel: "UVS" or "VS", "SWS", "MWS", "LWS", "DBL"
  double lambdaMaxNm = 0.0;
  std::optional<OilDroplet> droplet;
  bool betaBand = true;  // whether the template includes its beta band
};

// The receptor-noise-limited model's parameters (Vorobyev & Osorio 1998): the relative densities
// eta_i of the chromatic cones, the Weber fraction of one of them (the reference), from which every
// cone's noise follows as e_i = weber * sqrt(eta_ref / eta_i), and the achromatic Weber fraction.
struct ReceptorNoise {
  std::vector<double> relativeDensities;
  double weberFraction = 0.1;
  std::size_t weberReference = 0;  // index of the cone whose Weber fraction is weberFraction
  double achromaticWeberFraction = 0.1;
};

// The receptor-noise parameters every observer is held to (a definition file's columns, Python's
// observer dicts, makeObserver): relative densities within [1e-6, 1e6], Weber fractions within
// [1e-6, 10]. A Weber fraction of 0 made every distance infinite, one of inf or NaN every distance 0
// or NaN, and a density of inf a noise of NaN.
constexpr double kLeastRelativeDensity = 1e-6, kMostRelativeDensity = 1e6;
constexpr double kLeastWeberFraction = 1e-6, kMostWeberFraction = 10.0;

// Throws std::invalid_argument naming the parameter as an observer dict names it (densities[i],
// weber, weber_cone; and the achromatic Weber fraction) and its value where `noise` has one outside
// those ranges, or a reference cone that is not one of its densities'.
void checkReceptorNoise(const ReceptorNoise& noise);

// A visual system as its published parameters.
struct ObserverDefinition {
  std::string name;
  std::string description;
  std::vector<ConeClass> cones;  // the chromatic cones, shortest wavelength first
  std::optional<ConeClass> doubleCone;
  ReceptorNoise noise;
};

// A visual system tabulated on a grid: one sensitivity per chromatic channel, and an achromatic
// (double cone) sensitivity where the system has one.
struct Observer {
  std::string name;
  SpectralGrid grid;
  std::vector<std::string> channels;
  std::vector<std::vector<float>> sensitivities;
  std::string achromaticChannel;  // empty without an achromatic channel
  std::vector<float> achromatic;  // empty without an achromatic channel
  ReceptorNoise noise;

  bool hasAchromatic() const { return !achromatic.empty(); }
};

// A cone's sensitivity as pavo's sensmodel builds it: the pigment template divided by its peak,
// times the oil droplet's transmittance, divided by its integral over the grid (area 1, in 1/nm).
std::vector<float> coneSensitivity(const SpectralGrid& grid, const ConeClass& cone);

// The observer of a definition, tabulated on the grid (300-830 nm in 1 nm steps by default). Throws
// std::invalid_argument naming the observer for fewer than two cones, a density a cone short or
// over, or receptor noise that checkReceptorNoise refuses.
Observer makeObserver(const ObserverDefinition& definition, const SpectralGrid& grid = visionGrid());

// The built-in definitions (docs/vision.md lists each with its sources).
const std::vector<ObserverDefinition>& builtinObserverDefinitions();
// Every built-in observer, {name, description}: the parametric ones above, then pavo's tabulated
// averages avg.uv and avg.v (the Endler & Mielke table, compiled in).
std::vector<std::pair<std::string, std::string>> builtinObservers();
bool isBuiltinObserver(const std::string& name);
// Their names, comma-separated, for messages and help.
std::string builtinObserverNames();
// The definition of that name, or nullptr.
const ObserverDefinition* findObserverDefinition(const std::string& name);
// The built-in observer of that name on the grid (a tabulated one interpolated onto it, zero beyond
// its table); throws std::invalid_argument naming the known ones.
Observer namedObserver(const std::string& name, const SpectralGrid& grid = visionGrid());

// pavo's average ultraviolet- and violet-sensitive avian observers, avg.uv and avg.v, read from the
// online appendix of Endler & Mielke (2005, Biol J Linn Soc 86:405-431) in the layout pavo keeps it
// (data-raw/Endler_Mielke_2005_onlineappendix.txt: three header lines, then rows of a wavelength and
// eight sensitivities times 100: UVS, SWS, MWS, LWS of the UV eye, then VS, SWS, MWS, LWS of the
// violet eye, 300-700 nm in 1 nm steps). The sensitivities are divided by 100, as pavo does; each then
// has area 1. Returns {avg.uv, avg.v}, with pavo's coldist defaults for the noise (densities 1:2:2:4,
// Weber fraction 0.1 of the LWS cone). Columba compiles the table in (data/vision/).
std::vector<Observer> readEndlerMielkeObservers(std::istream& table);

}  // namespace columba
