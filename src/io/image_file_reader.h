#pragma once
// Reading the image files textures and environment maps are made of, in the formats Mitsuba's
// bitmap reads: OpenEXR (through OpenEXR), and PNG, JPEG, Radiance HDR, TGA, BMP, PNM, PSD and GIF
// (through stb_image).
#include <string>
#include <vector>
#include "io/image.h"

namespace columba {

// An image's pixels as floats: one channel (grey) or three (RGB), rows from the top of the image,
// alpha dropped.
struct PixelGrid {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;  // row-major, `channels` per pixel

  float at(int x, int y, int c) const { return values[(size_t(y) * size_t(width) + size_t(x)) * channels + c]; }
};

// The pixels of the image file at `path`. With `decodeSRGB`, files of 8 or 16 bits per channel
// (PNG, JPEG, ...) are decoded from the sRGB transfer curve to linear values, as Mitsuba does;
// OpenEXR and Radiance HDR files are linear as stored. InputError, naming the file, for a file
// that cannot be read, an empty or oversized image, or a channel layout other than grey,
// grey+alpha, RGB or RGBA.
PixelGrid readImagePixels(const std::string& path, bool decodeSRGB);

// The same file as a linear RGB image (a grey image's value in all three channels), decoded from
// sRGB where it is stored so: what an environment map is lit by.
Image readLinearRGBImage(const std::string& path);

}  // namespace columba
