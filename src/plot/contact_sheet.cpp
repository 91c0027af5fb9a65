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

Image makeContactSheet(const std::vector<ContactSheetEntry>& entries, int columns, int tileWidth,
                       const std::string& title) {
  if (entries.empty() || columns < 1 || tileWidth < 8) throw std::invalid_argument("empty contact sheet");
  columns = std::min(columns, int(entries.size()));  // fewer images than columns: no empty tiles
  const int margin = 12;
  int tileHeight = 0;
  for (const auto& e : entries)
    tileHeight = std::max(tileHeight, int(double(tileWidth) * e.image.height / e.image.width));
  const int rows = (int(entries.size()) + columns - 1) / columns;
  const int width = margin + columns * (tileWidth + margin);
  // Titles and labels wrap to their width; a label keeps at most kLabelLines lines.
  constexpr size_t kLabelLines = 4;
  const std::vector<std::string> titleLines = wrapText(title, float(width - 2 * margin), 3);
  const int titleLineHeight = int(Canvas::textHeight(3)) + 8, labelLineHeight = int(Canvas::textHeight(2)) + 4;
  const int titleHeight = titleLines.empty() ? 0 : 12 + int(titleLines.size()) * titleLineHeight;
  std::vector<std::vector<std::string>> labels;
  size_t labelLines = 1;
  for (const auto& e : entries) {
    labels.push_back(wrapText(e.label, float(tileWidth), 2));
    if (labels.back().size() > kLabelLines) labels.back().resize(kLabelLines);
    labelLines = std::max(labelLines, labels.back().size());
  }
  const int labelHeight = 12 + int(labelLines) * labelLineHeight;
  const int height = titleHeight + margin + rows * (tileHeight + labelHeight + margin);
  const Vec3 background = srgbColour(0.12f, 0.12f, 0.12f), ink = srgbColour(0.92f, 0.92f, 0.92f);
  Canvas canvas(width, height, background);
  for (size_t l = 0; l < titleLines.size(); ++l)
    canvas.text(margin, 12 + float(l * titleLineHeight), titleLines[l], ink, 3);
  for (size_t i = 0; i < entries.size(); ++i) {
    const Image& src = entries[i].image;
    int h = std::max(1, int(double(tileWidth) * src.height / src.width));
    int x0 = margin + int(i % columns) * (tileWidth + margin);
    int y0 = titleHeight + margin + int(i / columns) * (tileHeight + labelHeight + margin);
    canvas.drawImage(x0, y0, resizeImage(src, tileWidth, h));
    for (size_t l = 0; l < labels[i].size(); ++l)  // right under its image
      canvas.text(float(x0), float(y0 + h + 8 + int(l) * labelLineHeight), labels[i][l], ink, 2);
  }
  return canvas.image();
}

}  // namespace columba
