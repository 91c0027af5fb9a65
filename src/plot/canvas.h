#pragma once
// A canvas for charts drawn with Cairo: filled rectangles, anti-aliased lines, markers, images
// and text in a real font (DejaVu Sans, through fontconfig). A raster canvas gives an Image (in
// linear RGB, so the usual PNG writer encodes it); a vector one writes an SVG or PDF file (the
// PDF's text stays text; Cairo 1.16 writes SVG text as glyph outlines). Colours are given in
// linear RGB.
#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include "core/vector.h"
#include "io/image.h"

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace columba {

class Canvas {
 public:
  // A raster canvas of width x height pixels.
  Canvas(int width, int height, const Vec3& background);
  // A vector canvas of width x height points writing `path`, .svg or .pdf, on finish().
  Canvas(const std::string& path, int width, int height, const Vec3& background);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  // Copies `image` with its top-left corner at (x, y), clipped to the canvas.
  void drawImage(int x, int y, const Image& image);
  void fillRect(float x0, float y0, float x1, float y1, const Vec3& colour);
  // A line `thickness` pixels wide, solid or dashed.
  void line(Vec2 a, Vec2 b, const Vec3& colour, float thickness = 1.0f, bool dashed = false);
  // A polyline through `points`, solid or dashed, drawn only inside the rectangle `clip`
  // (x0, y0, x1, y1).
  void polyline(const std::vector<Vec2>& points, const Vec3& colour, float thickness, bool dashed,
                const std::array<float, 4>& clip);
  // A filled disk with a dark rim: a data point.
  void marker(Vec2 centre, float radius, const Vec3& colour);
  // Text with its top-left corner at (x, y); `scale` 2 is the body size (13 px), 3 a title's.
  void text(float x, float y, const std::string& s, const Vec3& colour, int scale = 2);
  static float textWidth(const std::string& s, int scale = 2);
  static float textHeight(int scale = 2);

  // A raster canvas's pixels.
  Image image() const;
  // Writes a vector canvas's file; throws std::runtime_error naming it where Cairo cannot.
  void finish();

 private:
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
  std::string path_;       // of a vector canvas
  std::string temporary_;  // what it is written to until finish() renames it; empty once renamed
};

// Whether `path` names a vector figure: .svg or .pdf, in any letter case.
bool isVectorFigurePath(const std::string& path);

// A figure of width x height drawn by `draw`, written to `path`: .png as pixels (with `metadata`),
// .svg or .pdf as vectors (width and height in points). Throws std::runtime_error for another
// extension or a file Cairo cannot write.
void writeFigure(const std::string& path, int width, int height, const Vec3& background,
                 const std::function<void(Canvas&)>& draw, const ImageMetadata& metadata = {});

// `text` broken into lines no wider than `maxWidth` pixels at `scale`, at " | " separators or
// else at spaces.
std::vector<std::string> wrapText(const std::string& text, float maxWidth, int scale);

// sRGB-encoded colour components (0..1) to the linear values the canvas takes.
Vec3 srgbColour(float r, float g, float b);

}  // namespace columba
