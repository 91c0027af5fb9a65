#include "plot/hemisphere_chart.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include "core/math.h"
#include "plot/canvas.h"

namespace columba {

namespace {
constexpr float kMargin = 60.0f;
}  // namespace

Image drawHemisphereChart(const Image& disk, const HemisphereChart& chart) {
  const float size = float(disk.width);
  const int width = std::max(int(size + 2 * kMargin) + 140, 640);  // room on the right for the axis label
  const std::vector<std::string> subtitle = wrapText(chart.subtitle, float(width) - 20, 2);
  const float lineHeight = Canvas::textHeight(2) + 6;
  const float top = 20 + Canvas::textHeight(3) + 10 + lineHeight * subtitle.size() + 20;
  const int height = int(top + size + kMargin);
  const Vec3 white(1, 1, 1), black(0, 0, 0), grey = srgbColour(0.55f, 0.55f, 0.55f);
  const Vec3 lightColour = srgbColour(1.0f, 0.85f, 0.1f), mirrorColour = srgbColour(0.2f, 0.9f, 1.0f);
  Canvas canvas(width, height, white);
  canvas.text(0.5f * (width - Canvas::textWidth(chart.title, 3)), 20, chart.title, black, 3);
  for (size_t i = 0; i < subtitle.size(); ++i)
    canvas.text(0.5f * (width - Canvas::textWidth(subtitle[i])), 20 + Canvas::textHeight(3) + 10 + lineHeight * i,
                subtitle[i], black);
  const float x0 = kMargin, y0 = top, radius = 0.5f * size;
  const Vec2 centre(x0 + radius, y0 + radius);
  // Only the disk: the corners, which no direction maps to, stay white.
  Image shown = disk;
  for (int y = 0; y < disk.height; ++y)
    for (int x = 0; x < disk.width; ++x) {
      float u = 2.0f * (x + 0.5f) / disk.width - 1.0f, v = 2.0f * (y + 0.5f) / disk.height - 1.0f;
      if (u * u + v * v >= 1.0f)
        for (int c = 0; c < 3; ++c) shown.pixel(x, y)[c] = 1.0f;
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
  return canvas.image();
}

}  // namespace columba
