#pragma once
// A small raster canvas for charts: filled rectangles, lines and bitmap text (stb_easy_font),
// drawn in linear RGB into an Image so the usual PNG writer encodes it.
#include <string>
#include <vector>
#include "core/vector.h"
#include "io/image.h"

namespace columba {

class Canvas {
 public:
  Canvas(int width, int height, const Vec3& background);
  // Copies `image` with its top-left corner at (x, y), clipped to the canvas.
  void drawImage(int x, int y, const Image& image);
  void fillRect(float x0, float y0, float x1, float y1, const Vec3& colour);
  // A line `thickness` pixels wide.
  void line(Vec2 a, Vec2 b, const Vec3& colour, float thickness = 1.0f);
  // Text with its top-left corner at (x, y); `scale` enlarges the 1-pixel bitmap font.
  void text(float x, float y, const std::string& s, const Vec3& colour, int scale = 2);
  static float textWidth(const std::string& s, int scale = 2);
  static float textHeight(int scale = 2);
  const Image& image() const { return image_; }

 private:
  void blend(int x, int y, const Vec3& colour, float coverage);
  Image image_;
};

// `text` broken into lines no wider than `maxWidth` pixels at `scale`, at " | " separators or
// else at spaces.
std::vector<std::string> wrapText(const std::string& text, float maxWidth, int scale);

// sRGB-encoded colour components (0..1) to the linear values the canvas stores.
Vec3 srgbColour(float r, float g, float b);

}  // namespace columba
