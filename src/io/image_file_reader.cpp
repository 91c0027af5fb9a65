#include "io/image_file_reader.h"

#include <stb_image.h>

#include <cstdio>
#include <memory>

#include "core/error.h"

namespace columba {

namespace {
// Larger images are refused rather than allocated: a corrupt header must not exhaust memory.
constexpr size_t kMaxPixels = size_t(1) << 28;

bool isOpenEXR(const std::string& path) {
  unsigned char magic[4] = {};
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  return file && std::fread(magic, 1, 4, file.get()) == 4 && magic[0] == 0x76 && magic[1] == 0x2f && magic[2] == 0x31 &&
         magic[3] == 0x01;
}

PixelGrid fromRGB(const Image& image) {
  PixelGrid grid;
  grid.width = image.width;
  grid.height = image.height;
  grid.channels = 3;
  grid.values = image.rgb;
  return grid;
}

// Reads through stb_image: floats for Radiance HDR files, 8- or 16-bit integers otherwise
// (scaled to [0, 1] and decoded from sRGB when asked).
PixelGrid readWithStb(const std::string& path, bool decodeSRGB) {
  const SourceLocation where{path, 0};
  int width = 0, height = 0, stored = 0;
  if (!stbi_info(path.c_str(), &width, &height, &stored))
    throw InputError(where, std::string("cannot read the image: ") + stbi_failure_reason());
  if (width <= 0 || height <= 0) throw InputError(where, "the image is empty");
  if (size_t(width) * size_t(height) > kMaxPixels)
    throw InputError(where,
                     "the image is too large (" + std::to_string(width) + " x " + std::to_string(height) + " pixels)");
  if (stored < 1 || stored > 4)
    throw InputError(where, "the image has " + std::to_string(stored) +
                                " channels; grey, grey and alpha, RGB or RGBA are supported");
  PixelGrid grid;
  grid.width = width;
  grid.height = height;
  grid.channels = stored <= 2 ? 1 : 3;
  const size_t pixels = size_t(width) * size_t(height);
  grid.values.resize(pixels * size_t(grid.channels));
  // Keeps channel c of pixel i, mapped by `value`, and drops alpha.
  auto keep = [&](auto* data, auto value) {
    if (!data) throw InputError(where, std::string("cannot read the image's pixels: ") + stbi_failure_reason());
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < grid.channels; ++c)
        grid.values[i * size_t(grid.channels) + size_t(c)] = value(data[i * size_t(stored) + size_t(c)]);
    stbi_image_free(data);
  };
  int w = 0, h = 0, n = 0;
  if (stbi_is_hdr(path.c_str())) {
    keep(stbi_loadf(path.c_str(), &w, &h, &n, stored), [](float v) { return v; });
  } else if (stbi_is_16_bit(path.c_str())) {
    keep(stbi_load_16(path.c_str(), &w, &h, &n, stored), [&](stbi_us v) {
      const float encoded = float(v) / 65535.0f;
      return decodeSRGB ? srgbToLinear(encoded) : encoded;
    });
  } else {
    keep(stbi_load(path.c_str(), &w, &h, &n, stored), [&](stbi_uc v) {
      const float encoded = float(v) / 255.0f;
      return decodeSRGB ? srgbToLinear(encoded) : encoded;
    });
  }
  return grid;
}
}  // namespace

PixelGrid readImagePixels(const std::string& path, bool decodeSRGB) {
  if (isOpenEXR(path)) return fromRGB(readEXR(path));
  return readWithStb(path, decodeSRGB);
}

Image readLinearRGBImage(const std::string& path) {
  const PixelGrid grid = readImagePixels(path, true);
  Image image(grid.width, grid.height);
  const size_t pixels = size_t(grid.width) * size_t(grid.height);
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) image.rgb[3 * i + c] = grid.values[i * grid.channels + (grid.channels == 1 ? 0 : c)];
  return image;
}

}  // namespace columba
