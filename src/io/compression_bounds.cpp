#include "io/compression_bounds.h"

#include <algorithm>
#include <cstring>

namespace columba {

namespace {
// Deflate's longest match, 258 bytes, coded in two bits.
constexpr double kDeflateBytesPerByte = 1032;
}  // namespace

double mostPixelsPerByte(const unsigned char* head, size_t size) {
  auto starts = [&](const char* magic, size_t n) { return size >= n && std::memcmp(head, magic, n) == 0; };
  if (starts("\x89PNG\r\n\x1a\n", 8)) {
    // Deflated rows at the bits per pixel of the IHDR chunk: depth times the colour type's samples.
    int bits = 1;
    if (size >= 26 && std::memcmp(head + 12, "IHDR", 4) == 0) {
      const int samples[7] = {1, 0, 3, 1, 2, 0, 4};
      bits = std::max(1, head[24] * (head[25] < 7 ? samples[head[25]] : 1));
    }
    return kDeflateBytesPerByte * 8 / bits;
  }
  if (starts("\xff\xd8", 2)) return 512;             // JPEG: a bit of code at least for each 8 x 8 block
  if (starts("BM", 2)) return 8;                     // BMP: uncompressed (stb_image reads no RLE), a bit a pixel
  if (starts("GIF8", 4)) return 2731;                // GIF: a 12-bit LZW code stands for 4096 pixels at most
  if (starts("8BPS", 4)) return 64;                  // PSD: PackBits runs of 128 bytes in 2
  if (starts("P5", 2) || starts("P6", 2)) return 1;  // binary PNM: a byte a sample
  if (starts("#?", 2)) return 16;  // Radiance HDR: runs of 127 in 2 bytes, for each of 4 bytes a pixel
  return 64;                       // TGA: RLE packets of 128 pixels in 2 bytes at least
}

double mostEXRBytesPerByte(int compression) {
  switch (compression) {
    case 0:  // NO_COMPRESSION
      return 1;
    case 1:  // RLE: runs of 128 bytes in 2
      return 64;
    case 5:  // PXR24: deflated 24-bit floats
      return kDeflateBytesPerByte * 4 / 3;
    case 6:  // B44, B44A: a 4 x 4 block of half values (32 bytes) in 3 bytes at least
    case 7:
      return 11;
    case 8:  // DWAA, DWAB: an 8 x 8 block of half values (128 bytes) in 4 bytes, then deflated
    case 9:
      return 32 * kDeflateBytesPerByte;
    default:  // ZIPS, ZIP (deflate); PIZ (Huffman runs of 256 values in 10 bits at least)
      return kDeflateBytesPerByte;
  }
}

}  // namespace columba
