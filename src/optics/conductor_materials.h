#pragma once
// Measured complex indices of refraction of metals, for Mitsuba's conductor `material` names.
// Ag, Al, Au, Cr and Cu: published tables (the sources are named beside each in
// conductor_materials.cpp), as taken from the public-domain refractiveindex.info database, over
// about 300-1000 nm. The others (a-C, W, Cu_palik, ...): Mitsuba's own tables, compiled in from
// data/ior/ (Palik's handbooks and the LLNL/CXRO tables via the LUXPOP database; its README).
// Linear between the measured wavelengths.
#include <optional>
#include <string>
#include "core/spectrum.h"

namespace columba {

struct ConductorIndex {
  SpectralDistribution eta, k;
};

// The index of the material Mitsuba calls `name` ("Au", "W", "a-C", ...), or nullopt.
std::optional<ConductorIndex> conductorIndex(const std::string& name);
// The names conductorIndex knows, for error messages ("Ag, Al, AlAs, ...").
std::string conductorNames();

}  // namespace columba
