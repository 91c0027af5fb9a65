#pragma once
// A contact sheet: images scaled into a grid of equal tiles, each labelled below.
#include <string>
#include <vector>
#include "io/image.h"

namespace columba {

struct ContactSheetEntry {
  Image image;
  std::string label;
};

// `tileWidth` pixels per tile; each image keeps its aspect ratio (area-averaged when shrunk).
// Fewer images than `columns` make one row of as many tiles as there are images.
Image makeContactSheet(const std::vector<ContactSheetEntry>& entries, int columns, int tileWidth,
                       const std::string& title);

// The sheet written to `path`: .png (pixels, with `metadata`), .svg or .pdf (vector: the images
// embedded, the title and labels text).
void writeContactSheet(const std::string& path, const std::vector<ContactSheetEntry>& entries, int columns,
                       int tileWidth, const std::string& title, const ImageMetadata& metadata = {});

// `image` resampled to width x height by averaging the source pixels under each target pixel
// (nearest pixel when enlarging).
Image resizeImage(const Image& image, int width, int height);

}  // namespace columba
