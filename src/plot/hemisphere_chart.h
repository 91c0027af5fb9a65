#pragma once
// A scatterometer image made readable: the hemisphere disk with rings of equal polar angle, the
// azimuth-zero axis named, the light and its mirror direction marked, a title, and a brightness
// bar that says which value a pixel's grey level stands for.
#include <string>
#include "io/image.h"

namespace columba {

struct HemisphereChart {
  std::string title, subtitle;
  std::string axisLabel = "across barbules (phi = 0)";
  float lightTheta = 0.0f, lightPhi = 0.0f;  // radians; the mirror direction is at phi + pi
  std::string valueLabel = "value";          // what the disk's pixels hold, above the bar
};

// `disk`: a square image whose inscribed disk maps to the hemisphere as the `bsdfvisualizer`
// sensor maps it (r = theta / (pi/2), phi = atan2(v, u), v growing downward with the row). Its
// values are shown as they are (1 is white, brighter clips), as the bar beside it says.
Image drawHemisphereChart(const Image& disk, const HemisphereChart& chart);
// The chart written to `path`: .png (pixels, with `metadata`), .svg or .pdf (vector; the disk an
// embedded image).
void writeHemisphereChart(const std::string& path, const Image& disk, const HemisphereChart& chart,
                          const ImageMetadata& metadata = {});

}  // namespace columba
