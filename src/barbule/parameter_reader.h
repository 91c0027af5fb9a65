#pragma once
// The one reader of a barbule's parameters, for every front end: a scene's <bsdf
// type="barbulebsdf">, and `columba bsdf` and Python's BarbuleBSDF, which build Properties from
// their options and keyword arguments (as Mitsuba's load_dict does), so that all take the same
// values with the same checks.
#include <optional>
#include <string>
#include <vector>

#include "barbule/parameters.h"
#include "barbule/point_model.h"
#include "core/properties.h"

namespace columba {

// preset (a string; the parameters given beside it override it), b, phi_0, phi_1, mu, H, height,
// film_ior (a number, a named index, "keratin" by default, or a spectrum of n against
// wavelength) or film_cauchy_a and film_cauchy_b, ext_ior ("air" by default), melanin (a
// spectrum or a number; the embedded measured table by default), layers. Throws InputError
// (props.error) for values the model cannot take. Values it takes that are probably a mistake
// are returned in `implausible` for the caller to warn about in its own way.
BarbuleParameters readBarbuleParameters(const Properties& props, std::optional<BarbuleParameterProblem>& implausible);
// The film's part of them alone, into `p`: height, film_ior or film_cauchy_a and film_cauchy_b,
// ext_ior, layers (for barbule BSDFs with another cross-section); unchecked, as findProblem checks.
void readBarbuleFilm(const Properties& props, BarbuleParameters& p);
// Throws props.error naming the parameter for what findProblem finds in `p`.
void throwIfProblem(const Properties& props, const BarbuleParameters& p);

// The scene parameter of layer stack `index`: "layers" for 0, else "layers_<index>".
std::string layerStackParameter(int index);
// layers_1 to layers_15, numbered without gaps (BarbuleParameters::numberedLayerStacks): read by
// the scene's barbule BSDF alone, since only a feather's vertices choose among them.
std::vector<FilmStack> readNumberedLayerStacks(const Properties& props);

// The TRT lobe's quadrature: trt_offsets (1 to 64, default 4) and trt_angles (1 to 16, default 1).
BarbuleQuadrature readBarbuleQuadrature(const Properties& props);

}  // namespace columba
