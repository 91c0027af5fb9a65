#pragma once
// The text a scene, `columba bsdf --layers` and Python give a barbule's layers in, from the cortex
// down, items separated by commas:
//   INDEX:THICKNESS                  a layer: INDEX a number, a named index (air, water, ...),
//                                    `keratin`, `melanin` (optics/melanin_index.h) or a complex
//                                    N+Ki (K >= 0); THICKNESS in micrometres, not negative
//   rods(INDEX, DIAMETER, SPACING)   a row of parallel rods of INDEX (melanosomes, air channels)
//   rods(INDEX, DIAMETER, SPACING, MATRIX)   DIAMETER thick, SPACING apart centre to centre, in
//                                    MATRIX (keratin when not given), as effective layers
//                                    (optics/rod_layer.h)
//   [ITEMS] x N                      ITEMS repeated N times (1 to 1000)
// e.g. "[rods(melanin, 0.11, 0.15), keratin:0.04] x 9". A stack expands to at most
// kMaxFilmLayers layers.
#include <string>
#include <vector>

#include "optics/layered_film.h"

namespace columba {

inline constexpr size_t kMaxFilmLayers = 4096;

// The layers, each repeated part listed once with its count. Throws std::invalid_argument naming
// the piece that is wrong.
FilmStack parseFilmLayers(const std::string& text);

}  // namespace columba
