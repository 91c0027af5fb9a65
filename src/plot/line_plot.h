#pragma once
// Line charts with labelled axes, ticks and a legend, rendered to an image or written as PNG,
// SVG or PDF.
#include <string>
#include <vector>
#include "core/vector.h"
#include "io/image.h"

namespace columba {

struct PlotSeries {
  std::string label;
  std::vector<Vec2> points;  // (x, y) in data units
  Vec3 colour;               // linear RGB
  bool dashed = false;
  bool markers = false;  // a marker at each point, no line: measured data
};

struct LinePlot {
  std::string title, xLabel, yLabel;
  // Smaller lines under the title (the parameters of a measurement), wrapped to the width at its
  // " | " separators.
  std::string subtitle;
  float xMin = 0, xMax = 1, yMin = 0, yMax = 1;
  std::vector<PlotSeries> series;
};

Image renderLinePlot(const LinePlot& plot, int width, int height);
// The plot written to `path`: .png (pixels), .svg or .pdf (vector, its text as text; width and
// height in points).
void writeLinePlot(const std::string& path, const LinePlot& plot, int width, int height);

// Round tick positions covering [lo, hi], about `target` of them.
std::vector<float> niceTicks(float lo, float hi, int target);

}  // namespace columba
