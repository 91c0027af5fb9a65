#pragma once
// Reading image files of any format OpenImageIO knows (OpenEXR, Radiance HDR, PNG, JPEG, TIFF,
// TGA, BMP, ...): what textures and environment maps are made of.
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

// The pixels of the image file at `path`. With `decodeSRGB`, files stored with the sRGB transfer
// curve (integer formats such as 8- and 16-bit PNG and JPEG, unless the file declares itself linear)
// are decoded to linear values, as Mitsuba does; floating-point files (EXR, HDR) are linear as
// stored. InputError, naming the file, for a file that cannot be read, an empty image or a channel
// layout other than grey, grey+alpha, RGB or RGBA.
PixelGrid readImagePixels(const std::string& path, bool decodeSRGB);

// The same file as a linear RGB image (a grey image's value in all three channels), decoded from
// sRGB where it is stored so: what an environment map is lit by.
Image readLinearRGBImage(const std::string& path);

}  // namespace columba
