#include "io/hdr_scanlines.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace columba {

namespace {
// Where the pixels start: after the header's lines, the empty line that ends them and the
// resolution line ("-Y 512 +X 768").
size_t pixelDataStart(const unsigned char* bytes, size_t size) {
  size_t at = 0;
  auto nextLine = [&] {
    const size_t start = at;
    const void* newline = std::memchr(bytes + at, '\n', size - at);
    at = newline ? size_t(static_cast<const unsigned char*>(newline) - bytes) + 1 : size;
    return at - start;  // the line's length with its newline
  };
  nextLine();  // "#?RADIANCE"
  while (at < size && nextLine() > 1) {
  }
  nextLine();
  return at;
}
}  // namespace

void checkHDRScanlines(const std::string& path, const unsigned char* bytes, size_t size, int width, int height) {
  size_t at = pixelDataStart(bytes, size);
  int y = 0;
  auto fail = [&](const std::string& what) {
    return InputError({path, 0}, fmt::format("Radiance HDR scanline {} of {}: {}", y, height, what));
  };
  const uint64_t flatBytes = 4 * uint64_t(width) * uint64_t(height);
  auto checkFlat = [&] {  // from `at` to the end of the image, 4 bytes a pixel
    if (size - at < flatBytes)
      throw fail(fmt::format("the file ends {} bytes into {} bytes of pixels", size - at, flatBytes));
  };
  if (width < 8 || width >= 32768) return checkFlat();  // never run-length encoded
  for (; y < height; ++y) {
    if (size - at < 4) throw fail("the file ends before it");
    // A scanline that does not start with 2, 2 and a length below 32768 is a flat pixel: stb_image
    // then reads the whole image flat from here.
    if (bytes[at] != 2 || bytes[at + 1] != 2 || (bytes[at + 2] & 0x80)) return checkFlat();
    at += 4;
    for (int channel = 0; channel < 4; ++channel)
      for (int x = 0; x < width;) {
        if (at >= size) throw fail("the file ends inside it");
        int count = bytes[at++];
        const bool run = count > 128;
        if (run) count -= 128;
        if (count == 0) throw fail("a literal of no bytes");
        if (count > width - x)
          throw fail(fmt::format("{} of {} bytes from byte {} of channel {}, past its end", run ? "a run" : "a literal",
                                 count, x, channel));
        const size_t stored = run ? 1 : size_t(count);
        if (size - at < stored) throw fail("the file ends inside it");
        at += stored;
        x += count;
      }
  }
}

}  // namespace columba
