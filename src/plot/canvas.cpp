#include "plot/canvas.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>
#include <fontconfig/fontconfig.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "core/math.h"

namespace columba {

namespace {

constexpr const char* kFont = "DejaVu Sans";

double fontSize(int scale) { return 6.5 * scale; }

// Cairo draws in encoded sRGB.
double encoded(float linear) { return double(toSRGB8(linear)) / 255.0; }

void setColour(cairo_t* cr, const Vec3& c) { cairo_set_source_rgb(cr, encoded(c.x), encoded(c.y), encoded(c.z)); }

// Cairo's and fontconfig's caches, released at exit once fonts were used, so that leak checkers
// see only the program's own memory.
void releaseFontCachesAtExit() {
  static const bool registered = [] {
    std::atexit([] {
      cairo_debug_reset_static_data();
      FcFini();
    });
    return true;
  }();
  (void)registered;
}

void setFont(cairo_t* cr, int scale) {
  releaseFontCachesAtExit();
  cairo_select_font_face(cr, kFont, CAIRO_FONT_SLANT_NORMAL,
                         scale >= 3 ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, fontSize(scale));
}

// A context on a small image surface, for measuring text outside any canvas.
cairo_t* measuringContext() {
  thread_local struct Scratch {
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
    cairo_t* cr = cairo_create(surface);
    ~Scratch() {
      cairo_destroy(cr);
      cairo_surface_destroy(surface);
    }
  } scratch;
  return scratch.cr;
}

// The last four characters of a path in lower case: a figure's format.
std::string figureExtension(const std::string& path) {
  std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

}  // namespace

Vec3 srgbColour(float r, float g, float b) { return {srgbToLinear(r), srgbToLinear(g), srgbToLinear(b)}; }

Canvas::Canvas(int width, int height, const Vec3& background) {
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  cr_ = cairo_create(surface_);
  fillRect(0, 0, float(width), float(height), background);
}

// A vector canvas writes beside its file and renames it into place once complete, so that a
// failed or interrupted write leaves the file there before untouched.
Canvas::Canvas(const std::string& path, int width, int height, const Vec3& background)
    : path_(path), temporary_(path + ".tmp" + std::to_string(::getpid())) {
  const std::string extension = figureExtension(path);
  if (extension == ".svg")
    surface_ = cairo_svg_surface_create(temporary_.c_str(), width, height);
  else if (extension == ".pdf")
    surface_ = cairo_pdf_surface_create(temporary_.c_str(), width, height);
  else
    throw std::runtime_error("cannot write a chart as '" + path + "': give .png, .svg or .pdf");
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface_);
    std::remove(temporary_.c_str());
    throw std::runtime_error("cannot write '" + path + "'");
  }
  cr_ = cairo_create(surface_);
  fillRect(0, 0, float(width), float(height), background);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
  if (!temporary_.empty()) std::remove(temporary_.c_str());  // not renamed: unfinished or failed
}

void Canvas::drawImage(int x0, int y0, const Image& image) {
  cairo_surface_t* picture = cairo_image_surface_create(CAIRO_FORMAT_RGB24, image.width, image.height);
  cairo_surface_flush(picture);
  unsigned char* data = cairo_image_surface_get_data(picture);
  const int stride = cairo_image_surface_get_stride(picture);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      uint32_t rgb = uint32_t(toSRGB8(p[0])) << 16 | uint32_t(toSRGB8(p[1])) << 8 | uint32_t(toSRGB8(p[2]));
      reinterpret_cast<uint32_t*>(data + size_t(y) * size_t(stride))[x] = rgb;
    }
  cairo_surface_mark_dirty(picture);
  cairo_save(cr_);
  cairo_set_source_surface(cr_, picture, x0, y0);
  cairo_pattern_set_filter(cairo_get_source(cr_), CAIRO_FILTER_NEAREST);
  cairo_rectangle(cr_, x0, y0, image.width, image.height);
  cairo_fill(cr_);
  cairo_restore(cr_);
  cairo_surface_destroy(picture);
}

void Canvas::fillRect(float x0, float y0, float x1, float y1, const Vec3& colour) {
  setColour(cr_, colour);
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  cairo_fill(cr_);
}

void Canvas::line(Vec2 a, Vec2 b, const Vec3& colour, float thickness, bool dashed) {
  cairo_save(cr_);
  setColour(cr_, colour);
  cairo_set_line_width(cr_, thickness);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  if (dashed) {
    const double pattern[] = {6.0, 4.0};
    cairo_set_dash(cr_, pattern, 2, 0.0);
  }
  cairo_move_to(cr_, a.x, a.y);
  cairo_line_to(cr_, b.x, b.y);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Canvas::polyline(const std::vector<Vec2>& points, const Vec3& colour, float thickness, bool dashed,
                      const std::array<float, 4>& clip) {
  if (points.size() < 2) return;
  cairo_save(cr_);
  cairo_rectangle(cr_, clip[0], clip[1], clip[2] - clip[0], clip[3] - clip[1]);
  cairo_clip(cr_);
  setColour(cr_, colour);
  cairo_set_line_width(cr_, thickness);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  if (dashed) {
    const double pattern[] = {9.0, 6.0};
    cairo_set_dash(cr_, pattern, 2, 0.0);
  }
  cairo_move_to(cr_, points[0].x, points[0].y);
  for (size_t i = 1; i < points.size(); ++i) cairo_line_to(cr_, points[i].x, points[i].y);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Canvas::marker(Vec2 centre, float radius, const Vec3& colour) {
  cairo_save(cr_);
  cairo_new_path(cr_);  // no line from where the last text or path ended
  cairo_arc(cr_, centre.x, centre.y, radius, 0.0, 2.0 * kPi);
  setColour(cr_, colour);
  cairo_fill_preserve(cr_);
  setColour(cr_, colour * 0.35f);
  cairo_set_line_width(cr_, 1.0);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Canvas::text(float x, float y, const std::string& s, const Vec3& colour, int scale) {
  cairo_save(cr_);
  setColour(cr_, colour);
  setFont(cr_, scale);
  cairo_font_extents_t font;
  cairo_font_extents(cr_, &font);
  cairo_move_to(cr_, x, y + font.ascent);  // from the top-left corner to the baseline
  cairo_show_text(cr_, s.c_str());
  cairo_new_path(cr_);
  cairo_restore(cr_);
}

float Canvas::textWidth(const std::string& s, int scale) {
  cairo_t* cr = measuringContext();
  setFont(cr, scale);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, s.c_str(), &extents);
  return float(extents.x_advance);
}

float Canvas::textHeight(int scale) {
  cairo_t* cr = measuringContext();
  setFont(cr, scale);
  cairo_font_extents_t font;
  cairo_font_extents(cr, &font);
  return float(font.ascent + font.descent);
}

Image Canvas::image() const {
  cairo_surface_flush(surface_);
  const int width = cairo_image_surface_get_width(surface_), height = cairo_image_surface_get_height(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const uint32_t rgb = reinterpret_cast<const uint32_t*>(data + size_t(y) * size_t(stride))[x];
      float* p = image.pixel(x, y);
      p[0] = srgbToLinear(float((rgb >> 16) & 0xff) / 255.0f);
      p[1] = srgbToLinear(float((rgb >> 8) & 0xff) / 255.0f);
      p[2] = srgbToLinear(float(rgb & 0xff) / 255.0f);
    }
  return image;
}

void Canvas::finish() {
  cairo_show_page(cr_);
  cairo_surface_finish(surface_);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write '" + path_ + "': " + cairo_status_to_string(cairo_surface_status(surface_)));
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot write '" + path_ +
                             "': cannot rename the temporary file into place: " + std::strerror(errno));
  temporary_.clear();
}

bool isVectorFigurePath(const std::string& path) {
  const std::string extension = figureExtension(path);
  return extension == ".svg" || extension == ".pdf";
}

void writeFigure(const std::string& path, int width, int height, const Vec3& background,
                 const std::function<void(Canvas&)>& draw, const ImageMetadata& metadata) {
  if (figureExtension(path) == ".png") {
    Canvas canvas(width, height, background);
    draw(canvas);
    writePNG(path, canvas.image(), metadata);
    return;
  }
  Canvas canvas(path, width, height, background);
  draw(canvas);
  canvas.finish();
}

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
