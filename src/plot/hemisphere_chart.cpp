#include "plot/hemisphere_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include "core/math.h"
#include "core/spectrum.h"
#include "plot/canvas.h"
#include "plot/line_plot.h"

namespace columba {

namespace {
constexpr float kMargin = 60.0f;
constexpr float kBarWidth = 18.0f;

// Where everything goes for a disk of this size.
struct Layout {
  int width = 0, height = 0;
  float top = 0.0f;   // of the disk
  float barX = 0.0f;  // left edge of the brightness bar
  std::vector<std::string> subtitle;
};

Layout layoutFor(const Image& disk, const HemisphereChart& chart) {
  Layout l;
  const float size = float(disk.width);
  // Right of the disk: the axis label (out to 1.1 radii and its text), then the brightness bar
  // and its tick labels.
  l.barX = kMargin + 1.05f * size + 110.0f;
  l.width = std::max(int(l.barX) + 110, 640);
  l.subtitle = wrapText(chart.subtitle, float(l.width) - 20, 2);
  const float lineHeight = Canvas::textHeight(2) + 6;
  l.top = 20 + Canvas::textHeight(3) + 10 + lineHeight * float(l.subtitle.size()) + 20;
  l.height = int(l.top + size + kMargin);
  return l;
}

void drawChart(Canvas& canvas, const Image& disk, const HemisphereChart& chart, const Layout& layout) {
  const float size = float(disk.width);
  const Vec3 black(0, 0, 0), grey = srgbColour(0.55f, 0.55f, 0.55f);
  const Vec3 lightColour = srgbColour(1.0f, 0.85f, 0.1f), mirrorColour = srgbColour(0.2f, 0.9f, 1.0f);
  const float width = float(layout.width);
  canvas.text(0.5f * (width - Canvas::textWidth(chart.title, 3)), 20, chart.title, black, 3);
  const float lineHeight = Canvas::textHeight(2) + 6;
  for (size_t i = 0; i < layout.subtitle.size(); ++i)
    canvas.text(0.5f * (width - Canvas::textWidth(layout.subtitle[i])),
                20 + Canvas::textHeight(3) + 10 + lineHeight * float(i), layout.subtitle[i], black);
  const float x0 = kMargin, y0 = layout.top, radius = 0.5f * size;
  const Vec2 centre(x0 + radius, y0 + radius);
  // Only the disk: the corners, which no direction maps to, stay white.
  Image shown = disk;
  float brightest = 0.0f;
  for (int y = 0; y < disk.height; ++y)
    for (int x = 0; x < disk.width; ++x) {
      float u = 2.0f * (x + 0.5f) / disk.width - 1.0f, v = 2.0f * (y + 0.5f) / disk.height - 1.0f;
      if (u * u + v * v >= 1.0f)
        for (int c = 0; c < 3; ++c) shown.pixel(x, y)[c] = 1.0f;
      else if (float Y = linearRGBToXYZ(Vec3(disk.pixel(x, y)[0], disk.pixel(x, y)[1], disk.pixel(x, y)[2])).y;
               std::isfinite(Y))
        brightest = std::max(brightest, Y);
    }
  canvas.drawImage(int(x0), int(y0), shown);
  // A direction at polar angle theta and azimuth phi, in chart pixels.
  auto at = [&](float theta, float phi) {
    float r = radius * theta / kHalfPi;
    return Vec2(centre.x + r * std::cos(phi), centre.y + r * std::sin(phi));
  };
  for (float ringDeg : {30.0f, 60.0f, 90.0f}) {
    const int segments = 180;
    for (int k = 0; k < segments; k += (ringDeg < 90.0f ? 2 : 1))  // inner rings dashed
      canvas.line(at(degToRad(ringDeg), kTwoPi * k / segments), at(degToRad(ringDeg), kTwoPi * (k + 1) / segments),
                  ringDeg < 90.0f ? grey : black, 1.5f);
    std::string label = fmt::format("{:g} deg", ringDeg);
    Vec2 p = at(degToRad(ringDeg), -0.25f * kPi);
    canvas.text(p.x + 4, p.y - Canvas::textHeight() - 2, label, ringDeg < 90.0f ? grey : black);
  }
  // The phi = 0 axis, from the centre past the rim, named.
  canvas.line(centre, at(kHalfPi * 1.08f, 0.0f), black, 1.5f);
  Vec2 end = at(kHalfPi * 1.1f, 0.0f);
  canvas.text(end.x + 4, end.y - 0.5f * Canvas::textHeight(), "phi = 0", black);
  canvas.text(end.x + 4, end.y + 0.5f * Canvas::textHeight() + 2, "across", black);
  canvas.text(end.x + 4, end.y + 1.5f * Canvas::textHeight() + 4, "barbules", black);
  // Markers: a cross for the light, a ring for its mirror direction.
  auto cross = [&](Vec2 p, const Vec3& colour) {
    canvas.line(Vec2(p.x - 7, p.y - 7), Vec2(p.x + 7, p.y + 7), colour, 3.0f);
    canvas.line(Vec2(p.x - 7, p.y + 7), Vec2(p.x + 7, p.y - 7), colour, 3.0f);
  };
  auto ring = [&](Vec2 p, const Vec3& colour) {
    for (int k = 0; k < 24; ++k)
      canvas.line(Vec2(p.x + 8 * std::cos(kTwoPi * k / 24), p.y + 8 * std::sin(kTwoPi * k / 24)),
                  Vec2(p.x + 8 * std::cos(kTwoPi * (k + 1) / 24), p.y + 8 * std::sin(kTwoPi * (k + 1) / 24)), colour,
                  2.5f);
  };
  Vec2 light = at(chart.lightTheta, chart.lightPhi), mirror = at(chart.lightTheta, chart.lightPhi + kPi);
  cross(light, lightColour);
  ring(mirror, mirrorColour);
  // Legend under the disk.
  const float ly = y0 + size + 20;
  cross(Vec2(x0 + 10, ly + 6), lightColour);
  canvas.text(x0 + 24, ly, "light", black);
  ring(Vec2(x0 + 110, ly + 6), mirrorColour);
  canvas.text(x0 + 124, ly, "mirror direction", black);

  // The brightness bar: a grey of value v (linear, as the disk's pixels are shown) at height v;
  // values above 1 clip to white, and the disk's largest luminance is written under the bar.
  const float barTop = y0 + Canvas::textHeight() + 8, barBottom = y0 + size;
  const float barX = layout.barX;
  canvas.text(barX + 0.5f * kBarWidth - 0.5f * Canvas::textWidth(chart.valueLabel), y0, chart.valueLabel, black);
  const int steps = std::max(2, int(barBottom - barTop));
  for (int k = 0; k < steps; ++k) {
    const float v = (float(k) + 0.5f) / float(steps);
    const float yHigh = barBottom - (barBottom - barTop) * float(k + 1) / float(steps);
    const float yLow = barBottom - (barBottom - barTop) * float(k) / float(steps);
    canvas.fillRect(barX, yHigh, barX + kBarWidth, yLow + 0.5f, Vec3(v, v, v));
  }
  canvas.line(Vec2(barX, barTop), Vec2(barX + kBarWidth, barTop), black, 1.0f);
  canvas.line(Vec2(barX, barBottom), Vec2(barX + kBarWidth, barBottom), black, 1.0f);
  canvas.line(Vec2(barX, barTop), Vec2(barX, barBottom), black, 1.0f);
  canvas.line(Vec2(barX + kBarWidth, barTop), Vec2(barX + kBarWidth, barBottom), black, 1.0f);
  for (float v : niceTicks(0.0f, 1.0f, 4)) {
    const float y = barBottom - (barBottom - barTop) * v;
    canvas.line(Vec2(barX + kBarWidth, y), Vec2(barX + kBarWidth + 5, y), black, 1.0f);
    canvas.text(barX + kBarWidth + 8, y - 0.5f * Canvas::textHeight(), fmt::format("{:g}", v), black);
  }
  canvas.text(barX - 20, barBottom + 8, fmt::format("largest {:.3g}", brightest), black);
  if (brightest > 1.0f) canvas.text(barX - 20, barBottom + 8 + lineHeight, "(clipped above 1)", black);
}
}  // namespace

Image drawHemisphereChart(const Image& disk, const HemisphereChart& chart) {
  const Layout layout = layoutFor(disk, chart);
  Canvas canvas(layout.width, layout.height, Vec3(1, 1, 1));
  drawChart(canvas, disk, chart, layout);
  return canvas.image();
}

void writeHemisphereChart(const std::string& path, const Image& disk, const HemisphereChart& chart,
                          const ImageMetadata& metadata) {
  const Layout layout = layoutFor(disk, chart);
  writeFigure(
      path, layout.width, layout.height, Vec3(1, 1, 1), [&](Canvas& canvas) { drawChart(canvas, disk, chart, layout); },
      metadata);
}

}  // namespace columba
