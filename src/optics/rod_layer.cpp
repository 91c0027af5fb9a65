#include "optics/rod_layer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace columba {

namespace {

// The area of a disc of radius r below the chord at height t from its centre (-r <= t <= r):
// its derivative in t is the chord's length 2 sqrt(r^2 - t^2).
double discAreaBelow(double r, double t) {
  t = std::clamp(t, -r, r);
  return r * r * std::acos(-t / r) + t * std::sqrt(r * r - t * t);
}

}  // namespace

double rodRowFraction(double diameterUm, double spacingUm, double z0, double z1) {
  const double r = 0.5 * diameterUm;
  if (!(z1 > z0)) return 0.0;
  // Depth z from the row's top is height r - z above the cylinders' axes.
  return (discAreaBelow(r, r - z0) - discAreaBelow(r, r - z1)) / (spacingUm * (z1 - z0));
}

std::vector<FilmLayer> rodRow(const LayerMaterial& rods, const LayerMaterial& matrix, float diameterUm, float spacingUm,
                              int slices) {
  if (!(diameterUm > 0.0f) || !(spacingUm >= diameterUm) || !std::isfinite(spacingUm))
    throw std::invalid_argument("a row of rods needs 0 < diameter <= spacing (rods that touch at most)");
  if (slices < 1) throw std::invalid_argument("a row of rods needs at least one slice");
  std::vector<FilmLayer> layers(static_cast<size_t>(slices));
  const double step = double(diameterUm) / slices;
  for (int i = 0; i < slices; ++i) {
    FilmLayer& layer = layers[size_t(i)];
    layer.material = rods;
    layer.matrix = matrix;
    layer.thicknessUm = float(step);
    layer.fraction = float(rodRowFraction(diameterUm, spacingUm, i * step, (i + 1) * step));
  }
  return layers;
}

}  // namespace columba
