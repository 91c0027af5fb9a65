#pragma once
// Measured complex indices of refraction of metals, for Mitsuba's conductor `material` names.
// Published tables (the sources are named beside each in conductor_materials.cpp), as taken from
// the public-domain refractiveindex.info database; tabulated over about 300-1000 nm and linear
// between the measured wavelengths.
#include <optional>
#include <string>
#include "core/spectrum.h"

namespace columba {

struct ConductorIndex {
  SpectralDistribution eta, k;
};

// The index of the metal Mitsuba calls `name` ("Au", "Ag", "Al", "Cu", "Cr"), or nullopt.
std::optional<ConductorIndex> conductorIndex(const std::string& name);
// The names conductorIndex knows, for error messages ("Ag, Al, Au, Cr, Cu").
std::string conductorNames();

}  // namespace columba
