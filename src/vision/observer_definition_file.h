#pragma once
// A visual system from its published parameters, as a biologist copies them from a paper's table
// (pavo's sensmodel takes the same): each cone's pigment peak, the oil droplet in front of it and
// the cone's relative density, one row a cone (docs/vision.md, "Observers from their parameters").
#include <istream>
#include <string>
#include "vision/observer.h"

namespace columba {

// Whether a table's first header cell, `firstColumn`, makes it a definition (`cone`) rather than
// a table of sensitivities.
bool isObserverDefinitionHeader(const std::string& firstColumn);

// The definition of a CSV file (commas, tabs or spaces; '#' lines are comments; NA or - for a value
// that does not apply) whose header names the columns
//   cone        UVS or VS, SWS, MWS, LWS (at least two chromatic cones) and optionally DBL
//   lambda_max  the pigment's peak absorbance, nm (Govardovskii et al. 2000 A1 template)
//   droplet     the oil droplet's type: T (transparent), C, Y, R or P; NA for none
// and optionally
//   lambda_cut  the droplet's cut-off wavelength, nm (needed for C, Y, R and P droplets)
//   lambda_mid  the droplet's mid-point, nm (else from lambda_cut by Hart & Vorobyev's 2005
//               regression for its type)
//   density     the cone's relative density (chromatic cones; else pavo's 1:2:2:4 by name)
//   weber       on one chromatic cone's row, that cone's Weber fraction (else 0.1 for the
//               longest cone); on DBL's row, the achromatic one (else 0.1)
//   beta        yes or no: whether the template has its beta band (default yes)
// Throws InputError naming `path` and the line for anything else. The observer is named `name`.
ObserverDefinition readObserverDefinition(std::istream& in, const std::string& path, const std::string& name);

}  // namespace columba
