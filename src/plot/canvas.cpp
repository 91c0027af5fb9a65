#include "plot/canvas.h"

// The header defines every helper as a static function; the canvas uses two of them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <vector>

namespace columba {

namespace {
struct FontVertex {
  float x, y, z;
  unsigned char colour[4];
};
}  // namespace

Vec3 srgbColour(float r, float g, float b) { return {srgbToLinear(r), srgbToLinear(g), srgbToLinear(b)}; }

Canvas::Canvas(int width, int height, const Vec3& background) : image_(width, height) {
  fillRect(0, 0, float(width), float(height), background);
}

void Canvas::drawImage(int x0, int y0, const Image& image) {
  for (int y = std::max(0, -y0); y < image.height && y0 + y < image_.height; ++y)
    for (int x = std::max(0, -x0); x < image.width && x0 + x < image_.width; ++x)
      std::copy_n(image.pixel(x, y), 3, image_.pixel(x0 + x, y0 + y));
}

void Canvas::blend(int x, int y, const Vec3& colour, float coverage) {
  if (x < 0 || y < 0 || x >= image_.width || y >= image_.height || coverage <= 0.0f) return;
  float* p = image_.pixel(x, y);
  coverage = std::min(coverage, 1.0f);
  for (int c = 0; c < 3; ++c) p[c] = p[c] * (1.0f - coverage) + colour[c] * coverage;
}

void Canvas::fillRect(float x0, float y0, float x1, float y1, const Vec3& colour) {
  for (int y = std::max(0, int(std::floor(y0))); y < std::min(image_.height, int(std::ceil(y1))); ++y)
    for (int x = std::max(0, int(std::floor(x0))); x < std::min(image_.width, int(std::ceil(x1))); ++x) {
      // Pixel coverage of the rectangle, so fractional edges are smooth.
      float cx = std::min(x1, float(x + 1)) - std::max(x0, float(x));
      float cy = std::min(y1, float(y + 1)) - std::max(y0, float(y));
      blend(x, y, colour, cx * cy);
    }
}

void Canvas::line(Vec2 a, Vec2 b, const Vec3& colour, float thickness) {
  // Coverage from the distance of each pixel centre to the segment (anti-aliased).
  float half = 0.5f * thickness;
  int x0 = int(std::floor(std::min(a.x, b.x) - half - 1)), x1 = int(std::ceil(std::max(a.x, b.x) + half + 1));
  int y0 = int(std::floor(std::min(a.y, b.y) - half - 1)), y1 = int(std::ceil(std::max(a.y, b.y) + half + 1));
  Vec2 d = b - a;
  float len2 = d.x * d.x + d.y * d.y;
  for (int y = std::max(y0, 0); y <= std::min(y1, image_.height - 1); ++y)
    for (int x = std::max(x0, 0); x <= std::min(x1, image_.width - 1); ++x) {
      Vec2 p(x + 0.5f, y + 0.5f);
      float t = len2 > 0 ? clampf(((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2, 0.0f, 1.0f) : 0.0f;
      Vec2 q = a + d * t;
      float dist = std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y));
      blend(x, y, colour, clampf(half + 0.5f - dist, 0.0f, 1.0f));
    }
}

void Canvas::text(float x, float y, const std::string& s, const Vec3& colour, int scale) {
  std::vector<FontVertex> buffer(4 * 64 * std::max<size_t>(s.size(), 1));
  std::string copy = s;
  int quads = stb_easy_font_print(0, 0, copy.data(), nullptr, buffer.data(), int(buffer.size() * sizeof(FontVertex)));
  for (int q = 0; q < quads; ++q) {
    const FontVertex* v = &buffer[size_t(q) * 4];
    fillRect(x + v[0].x * scale, y + v[0].y * scale, x + v[2].x * scale, y + v[2].y * scale, colour);
  }
}

float Canvas::textWidth(const std::string& s, int scale) {
  std::string copy = s;
  return float(stb_easy_font_width(copy.data()) * scale);
}

float Canvas::textHeight(int scale) { return 7.0f * scale; }

std::vector<std::string> wrapText(const std::string& text, float maxWidth, int scale) {
  // Pieces end after a " | " separator (kept at the line's end, trimmed) or, failing that, a space.
  std::vector<std::string> lines;
  std::string line;
  size_t start = 0;
  auto flush = [&] {
    while (!line.empty() && (line.back() == ' ' || line.back() == '|')) line.pop_back();
    if (!line.empty()) lines.push_back(line);
    line.clear();
  };
  while (start < text.size()) {
    size_t bar = text.find(" | ", start);
    size_t end = bar == std::string::npos ? text.size() : bar + 3;
    std::string piece = text.substr(start, end - start);
    if (!line.empty() && Canvas::textWidth(line + piece, scale) > maxWidth) flush();
    if (Canvas::textWidth(piece, scale) > maxWidth) {
      // A piece too wide on its own: at spaces.
      size_t from = 0;
      while (from < piece.size()) {
        size_t space = piece.find(' ', from);
        size_t to = space == std::string::npos ? piece.size() : space + 1;
        std::string word = piece.substr(from, to - from);
        if (!line.empty() && Canvas::textWidth(line + word, scale) > maxWidth) flush();
        line += word;
        from = to;
      }
    } else {
      line += piece;
    }
    start = end;
  }
  flush();
  return lines;
}

}  // namespace columba
