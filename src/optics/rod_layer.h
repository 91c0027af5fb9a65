#pragma once
// A row of melanosomes: parallel cylinders of one material (melanin rods, or air channels) with
// their axes in one plane parallel to the film, side by side at a spacing, in a matrix (keratin).
// Seen along the film's normal with spacings well below the wavelength, the row acts as a stack of
// thin layers whose permittivity is the volume average of the two materials at each depth: the
// effective-medium multilayer of the feather literature. docs/model.md, "Rows of melanosomes as
// effective layers", derives it and says what it leaves out.
#include <vector>

#include "optics/layered_film.h"

namespace columba {

// Slices a row is cut into: the reflectance of nine rows is then within 2e-3 of a fine slicing's
// over 300-830 nm (the error falls as 1 / slices^2; docs/model.md).
inline constexpr int kRodRowSlices = 16;

// The row as `slices` layers of equal thickness from its top, each holding the exact share of
// the cylinders' cross-section within it. Throws std::invalid_argument unless 0 < diameter <=
// spacing (cylinders that touch at most) and slices >= 1.
std::vector<FilmLayer> rodRow(const LayerMaterial& rods, const LayerMaterial& matrix, float diameterUm, float spacingUm,
                              int slices = kRodRowSlices);

// The share of a row's volume between depths z0 <= z1 (micrometres from its top, within [0, D])
// that the cylinders fill.
double rodRowFraction(double diameterUm, double spacingUm, double z0, double z1);

}  // namespace columba
