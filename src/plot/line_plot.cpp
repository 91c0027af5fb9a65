#include "plot/line_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "plot/canvas.h"

namespace columba {

std::vector<float> niceTicks(float lo, float hi, int target) {
  std::vector<float> ticks;
  if (!(hi > lo) || target < 1) return ticks;
  float raw = (hi - lo) / float(target);
  float magnitude = std::pow(10.0f, std::floor(std::log10(raw)));
  float step = magnitude;
  for (float m : {1.0f, 2.0f, 2.5f, 5.0f, 10.0f})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  for (float t = std::ceil(lo / step - 1e-4f) * step; t <= hi + 1e-4f * step; t += step)
    ticks.push_back(std::abs(t) < 1e-6f * step ? 0.0f : t);
  return ticks;
}

namespace {

void drawLinePlot(Canvas& canvas, const LinePlot& plot, int width, int height) {
  const Vec3 black(0, 0, 0), grid = srgbColour(0.88f, 0.88f, 0.88f);
  const std::vector<std::string> subtitle = wrapText(plot.subtitle, float(width) - 40, 2);
  const float lineHeight = Canvas::textHeight(2) + 6;
  // The legend stands right of the chart, so it never covers a curve.
  float legendWidth = 0;
  for (const PlotSeries& s : plot.series) legendWidth = std::max(legendWidth, Canvas::textWidth(s.label));
  const float legendSpace = plot.series.empty() ? 0.0f : legendWidth + 58;
  const float left = 90, right = float(width) - 20 - legendSpace, top = 80 + lineHeight * subtitle.size(),
              bottom = float(height) - 70;
  auto toPixel = [&](Vec2 p) {
    return Vec2(left + (p.x - plot.xMin) / (plot.xMax - plot.xMin) * (right - left),
                bottom - (p.y - plot.yMin) / (plot.yMax - plot.yMin) * (bottom - top));
  };
  for (float t : niceTicks(plot.xMin, plot.xMax, 8)) {
    float x = toPixel(Vec2(t, plot.yMin)).x;
    canvas.line(Vec2(x, top), Vec2(x, bottom), grid);
    canvas.line(Vec2(x, bottom), Vec2(x, bottom + 6), black);
    std::string label = fmt::format("{:g}", t);
    canvas.text(x - 0.5f * Canvas::textWidth(label), bottom + 12, label, black);
  }
  for (float t : niceTicks(plot.yMin, plot.yMax, 6)) {
    float y = toPixel(Vec2(plot.xMin, t)).y;
    canvas.line(Vec2(left, y), Vec2(right, y), grid);
    canvas.line(Vec2(left - 6, y), Vec2(left, y), black);
    std::string label = fmt::format("{:g}", t);
    canvas.text(left - 10 - Canvas::textWidth(label), y - 0.5f * Canvas::textHeight(), label, black);
  }
  canvas.line(Vec2(left, bottom), Vec2(right, bottom), black, 1.5f);
  canvas.line(Vec2(left, top), Vec2(left, bottom), black, 1.5f);
  canvas.text(0.5f * (left + right - Canvas::textWidth(plot.xLabel)), bottom + 40, plot.xLabel, black);
  canvas.text(10, top - 28, plot.yLabel, black);
  canvas.text(0.5f * (width - Canvas::textWidth(plot.title, 3)), 10, plot.title, black, 3);
  for (size_t i = 0; i < subtitle.size(); ++i)
    canvas.text(0.5f * (width - Canvas::textWidth(subtitle[i])), 10 + Canvas::textHeight(3) + 8 + lineHeight * i,
                subtitle[i], black);

  const std::array<float, 4> area = {left, top, right, bottom};
  for (const PlotSeries& s : plot.series) {
    std::vector<Vec2> pixels;
    for (const Vec2& p : s.points) pixels.push_back(toPixel(p));
    if (s.markers) {
      for (const Vec2& p : pixels)
        if (p.x >= left && p.x <= right && p.y >= top && p.y <= bottom) canvas.marker(p, 3.5f, s.colour);
    } else {
      canvas.polyline(pixels, s.colour, 2.5f, s.dashed, area);
    }
  }

  float lx = right + 20, ly = top;
  const float mid = 0.5f * Canvas::textHeight();
  for (const PlotSeries& s : plot.series) {
    if (s.markers)
      canvas.marker(Vec2(lx + 15, ly + mid), 3.5f, s.colour);
    else
      canvas.line(Vec2(lx, ly + mid), Vec2(lx + 30, ly + mid), s.colour, 2.5f, s.dashed);
    canvas.text(lx + 38, ly, s.label, black);
    ly += 22;
  }
}

}  // namespace

Image renderLinePlot(const LinePlot& plot, int width, int height) {
  Canvas canvas(width, height, srgbColour(1, 1, 1));
  drawLinePlot(canvas, plot, width, height);
  return canvas.image();
}

void writeLinePlot(const std::string& path, const LinePlot& plot, int width, int height) {
  writeFigure(path, width, height, srgbColour(1, 1, 1),
              [&](Canvas& canvas) { drawLinePlot(canvas, plot, width, height); });
}

}  // namespace columba
