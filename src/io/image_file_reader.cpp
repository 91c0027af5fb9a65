#include "io/image_file_reader.h"

#include <stb_image.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>

#include "core/error.h"
#include "io/compression_bounds.h"
#include "io/declared_image_size.h"
#include "io/hdr_scanlines.h"

namespace columba {

namespace {

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

std::vector<unsigned char> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0}, "cannot open the image file");
  return std::vector<unsigned char>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A file's bytes handed to stb_image through its callbacks, noting whether the decoder asked for
// bytes past the end: it reads zeros there without an error, so a file without its pixels would
// decode to a black image.
struct StbSource {
  const std::vector<unsigned char>& bytes;
  size_t at = 0;
  bool overran = false;

  // stb_image refills its buffer this many bytes at a time (a refill may come short at the end
  // of the file); any other read that comes short is data the decoder needed.
  static constexpr int kRefill = 128;

  static int read(void* user, char* data, int size) {
    auto& s = *static_cast<StbSource*>(user);
    const size_t n = std::min(size_t(std::max(size, 0)), s.bytes.size() - s.at);
    std::memcpy(data, s.bytes.data() + s.at, n);
    s.at += n;
    if (size > 0 && (n == 0 || (n < size_t(size) && size != kRefill))) s.overran = true;
    return int(n);
  }
  static void skip(void* user, int n) {
    auto& s = *static_cast<StbSource*>(user);
    s.at = n < 0 ? s.at : std::min(s.bytes.size(), s.at + size_t(n));
  }
  static int eof(void* user) {
    const auto& s = *static_cast<StbSource*>(user);
    return s.at >= s.bytes.size();
  }
  stbi_io_callbacks callbacks() const { return {&StbSource::read, &StbSource::skip, &StbSource::eof}; }
};

// Whether a JPEG's marker segments reach a start of scan before the end of the image: stb_image
// decodes one without any as a grey image, without an error.
bool hasJPEGScan(const std::vector<unsigned char>& bytes) {
  for (size_t at = 2; at + 1 < bytes.size();) {
    if (bytes[at] != 0xff) return false;
    const unsigned char marker = bytes[at + 1];
    if (marker == 0xda) return true;
    if (marker == 0xd9) return false;
    if (marker == 0xff || marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) {  // fill byte, no length
      at += marker == 0xff ? 1 : 2;
      continue;
    }
    if (at + 3 >= bytes.size()) return false;
    at += 2 + (size_t(bytes[at + 2]) << 8 | bytes[at + 3]);
  }
  return false;
}

// Throws InputError naming `path` when a PNG chunk before the end of the image declares more
// bytes than the file has left: stb_image allocates a chunk's declared length before reading it.
void checkPNGChunks(const std::string& path, const std::vector<unsigned char>& bytes) {
  for (size_t at = 8; at + 8 <= bytes.size();) {
    const uint32_t length = uint32_t(bytes[at]) << 24 | uint32_t(bytes[at + 1]) << 16 | uint32_t(bytes[at + 2]) << 8 |
                            uint32_t(bytes[at + 3]);
    const std::string type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    const size_t left = bytes.size() - at - 8;
    if (length > left)
      throw InputError({path, 0}, "PNG chunk '" + type + "' at byte " + std::to_string(at) + " declares " +
                                      std::to_string(length) + " bytes, but the file has " + std::to_string(left) +
                                      " bytes left");
    if (type == "IEND") return;
    at += 12 + size_t(length);
  }
}

// Reads through stb_image: floats for Radiance HDR files, 8- or 16-bit integers otherwise
// (scaled to [0, 1] and decoded from sRGB when asked). The declared size is checked against the
// file's length and the memory budget first, and the decoder must find all of its pixels.
PixelGrid readWithStb(const std::string& path, bool decodeSRGB) {
  const SourceLocation where{path, 0};
  const std::vector<unsigned char> bytes = readFileBytes(path);
  const int length = int(std::min(bytes.size(), size_t(INT32_MAX)));
  int width = 0, height = 0, stored = 0;
  if (!stbi_info_from_memory(bytes.data(), length, &width, &height, &stored))
    throw InputError(where, std::string("cannot read the image: ") + stbi_failure_reason());
  if (stored < 1 || stored > 4)
    throw InputError(where, "the image has " + std::to_string(stored) +
                                " channels; grey, grey and alpha, RGB or RGBA are supported");
  PixelGrid grid;
  grid.channels = stored <= 2 ? 1 : 3;
  checkDeclaredImageSize(path, width, height, grid.channels, sizeof(float), bytes.size(),
                         mostPixelsPerByte(bytes.data(), bytes.size()) * grid.channels);
  if (bytes.size() >= 8 && std::memcmp(bytes.data(), "\x89PNG", 4) == 0) checkPNGChunks(path, bytes);
  if (bytes.size() >= 2 && bytes[0] == 0xff && bytes[1] == 0xd8 && !hasJPEGScan(bytes))
    throw InputError(where, "the JPEG image has no scan: its pixels are not there");
  const bool hdr = stbi_is_hdr_from_memory(bytes.data(), length);
  if (hdr) checkHDRScanlines(path, bytes.data(), bytes.size(), width, height);
  grid.width = width;
  grid.height = height;
  const size_t pixels = size_t(width) * size_t(height);
  grid.values.resize(pixels * size_t(grid.channels));
  StbSource source{bytes};
  const stbi_io_callbacks io = source.callbacks();
  // Keeps channel c of pixel i, mapped by `value`, and drops alpha.
  auto keep = [&](auto* data, auto value) {
    std::unique_ptr<void, void (*)(void*)> owned(data, &stbi_image_free);
    if (!data) throw InputError(where, std::string("cannot read the image's pixels: ") + stbi_failure_reason());
    if (source.overran)
      throw InputError(where, "the file ends before the pixels its header declares (" + std::to_string(width) + " x " +
                                  std::to_string(height) + ") are all there");
    for (size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < grid.channels; ++c)
        grid.values[i * size_t(grid.channels) + size_t(c)] = value(data[i * size_t(stored) + size_t(c)]);
  };
  int w = 0, h = 0, n = 0;
  if (hdr) {
    keep(stbi_loadf_from_callbacks(&io, &source, &w, &h, &n, stored), [](float v) { return v; });
  } else if (stbi_is_16_bit_from_memory(bytes.data(), length)) {
    keep(stbi_load_16_from_callbacks(&io, &source, &w, &h, &n, stored), [&](stbi_us v) {
      const float encoded = float(v) / 65535.0f;
      return decodeSRGB ? srgbToLinear(encoded) : encoded;
    });
  } else {
    keep(stbi_load_from_callbacks(&io, &source, &w, &h, &n, stored), [&](stbi_uc v) {
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
