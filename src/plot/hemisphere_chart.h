#pragma once
// A scatterometer image made readable: the hemisphere disk with rings of equal polar angle, the
// azimuth-zero axis named, the light and its mirror direction marked, and a title.
#include <string>
#include "io/image.h"

namespace columba {

struct HemisphereChart {
  std::string title, subtitle;
  std::string axisLabel = "across barbules (phi = 0)";
  float lightTheta = 0.0f, lightPhi = 0.0f;  // radians; the mirror direction is at phi + pi
};

// `disk`: a square image whose inscribed disk maps to the hemisphere as the `bsdfvisualizer`
// sensor maps it (r = theta / (pi/2), phi = atan2(v, u), v growing downward with the row).
Image drawHemisphereChart(const Image& disk, const HemisphereChart& chart);

}  // namespace columba
