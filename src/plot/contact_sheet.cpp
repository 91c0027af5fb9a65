#include "plot/contact_sheet.h"

#include <algorithm>
#include <stdexcept>

#include "plot/canvas.h"

namespace columba {

Image resizeImage(const Image& image, int width, int height) {
  Image out(width, height);
  const double sx = double(image.width) / width, sy = double(image.height) / height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int x0 = int(x * sx), x1 = std::max(x0 + 1, int((x + 1) * sx));
      int y0 = int(y * sy), y1 = std::max(y0 + 1, int((y + 1) * sy));
      x1 = std::min(x1, image.width);
      y1 = std::min(y1, image.height);
      double sum[3] = {0, 0, 0};
      for (int v = y0; v < y1; ++v)
        for (int u = x0; u < x1; ++u)
          for (int c = 0; c < 3; ++c) sum[c] += image.pixel(u, v)[c];
      double n = double(x1 - x0) * (y1 - y0);
      for (int c = 0; c < 3; ++c) out.pixel(x, y)[c] = float(sum[c] / n);
    }
  return out;
}

namespace {

// Where everything goes, from the entries' sizes and texts.
struct SheetLayout {
  int columns = 0, width = 0, height = 0, tileHeight = 0, titleHeight = 0, labelHeight = 0;
  int titleLineHeight = 0, labelLineHeight = 0;
  std::vector<std::string> titleLines;
  std::vector<std::vector<std::string>> labels;
};

constexpr int kMargin = 12;

SheetLayout layoutSheet(const std::vector<ContactSheetEntry>& entries, int columns, int tileWidth,
                        const std::string& title) {
  if (entries.empty() || columns < 1 || tileWidth < 8) throw std::invalid_argument("empty contact sheet");
  SheetLayout l;
  l.columns = std::min(columns, int(entries.size()));  // fewer images than columns: no empty tiles
  for (const auto& e : entries)
    l.tileHeight = std::max(l.tileHeight, int(double(tileWidth) * e.image.height / e.image.width));
  const int rows = (int(entries.size()) + l.columns - 1) / l.columns;
  l.width = kMargin + l.columns * (tileWidth + kMargin);
  // Titles and labels wrap to their width; a label keeps at most kLabelLines lines.
  constexpr size_t kLabelLines = 4;
  l.titleLines = wrapText(title, float(l.width - 2 * kMargin), 3);
  l.titleLineHeight = int(Canvas::textHeight(3)) + 8;
  l.labelLineHeight = int(Canvas::textHeight(2)) + 4;
  l.titleHeight = l.titleLines.empty() ? 0 : 12 + int(l.titleLines.size()) * l.titleLineHeight;
  size_t labelLines = 1;
  for (const auto& e : entries) {
    l.labels.push_back(wrapText(e.label, float(tileWidth), 2));
    if (l.labels.back().size() > kLabelLines) l.labels.back().resize(kLabelLines);
    labelLines = std::max(labelLines, l.labels.back().size());
  }
  l.labelHeight = 12 + int(labelLines) * l.labelLineHeight;
  l.height = l.titleHeight + kMargin + rows * (l.tileHeight + l.labelHeight + kMargin);
  return l;
}

const Vec3 kSheetBackground = srgbColour(0.12f, 0.12f, 0.12f), kSheetInk = srgbColour(0.92f, 0.92f, 0.92f);

void drawSheet(Canvas& canvas, const std::vector<ContactSheetEntry>& entries, int tileWidth, const SheetLayout& l) {
  for (size_t k = 0; k < l.titleLines.size(); ++k)
    canvas.text(kMargin, 12 + float(k * l.titleLineHeight), l.titleLines[k], kSheetInk, 3);
  for (size_t i = 0; i < entries.size(); ++i) {
    const Image& src = entries[i].image;
    int h = std::max(1, int(double(tileWidth) * src.height / src.width));
    int x0 = kMargin + int(i % l.columns) * (tileWidth + kMargin);
    int y0 = l.titleHeight + kMargin + int(i / l.columns) * (l.tileHeight + l.labelHeight + kMargin);
    canvas.drawImage(x0, y0, resizeImage(src, tileWidth, h));
    for (size_t k = 0; k < l.labels[i].size(); ++k)  // right under its image
      canvas.text(float(x0), float(y0 + h + 8 + int(k) * l.labelLineHeight), l.labels[i][k], kSheetInk, 2);
  }
}

}  // namespace

Image makeContactSheet(const std::vector<ContactSheetEntry>& entries, int columns, int tileWidth,
                       const std::string& title) {
  const SheetLayout layout = layoutSheet(entries, columns, tileWidth, title);
  Canvas canvas(layout.width, layout.height, kSheetBackground);
  drawSheet(canvas, entries, tileWidth, layout);
  return canvas.image();
}

void writeContactSheet(const std::string& path, const std::vector<ContactSheetEntry>& entries, int columns,
                       int tileWidth, const std::string& title, const ImageMetadata& metadata) {
  const SheetLayout layout = layoutSheet(entries, columns, tileWidth, title);
  writeFigure(
      path, layout.width, layout.height, kSheetBackground,
      [&](Canvas& canvas) { drawSheet(canvas, entries, tileWidth, layout); }, metadata);
}

}  // namespace columba
