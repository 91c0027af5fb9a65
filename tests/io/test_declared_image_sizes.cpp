// Image files whose headers declare more than the file holds, or more than an image may take:
// every reader rejects them with an error naming the file and the declared size before it
// allocates for them, and a file whose pixels are missing is an error, not a black image.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>

#include "core/error.h"
#include "io/declared_image_size.h"
#include "io/image.h"
#include "io/image_file_reader.h"
#include "support/error_test_support.h"
#include "support/temp_dir_test.h"

using namespace columba;
using namespace columba::testing;

namespace {

std::string le16(int v) { return {char(v & 255), char((v >> 8) & 255)}; }
std::string le32(uint32_t v) { return le16(int(v & 0xffff)) + le16(int(v >> 16)); }
std::string be16(int v) { return {char((v >> 8) & 255), char(v & 255)}; }
std::string be32(uint32_t v) { return be16(int(v >> 16)) + be16(int(v & 0xffff)); }

std::string pngChunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  const uLong crc = crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()));
  return be32(uint32_t(data.size())) + body + be32(uint32_t(crc));
}
// An 8-bit RGB PNG of width x height pixels whose image data is 16 zero bytes, deflated.
std::string pngHeader(uint32_t width, uint32_t height) {
  const std::string zeros(16, '\0');
  std::string deflated(64, '\0');
  uLongf size = deflated.size();
  compress(reinterpret_cast<Bytef*>(deflated.data()), &size, reinterpret_cast<const Bytef*>(zeros.data()),
           zeros.size());
  deflated.resize(size);
  return std::string("\x89PNG\r\n\x1a\n", 8) +
         pngChunk("IHDR", be32(width) + be32(height) + std::string("\x08\x02\x00\x00\x00", 5)) +
         pngChunk("IDAT", deflated) + pngChunk("IEND", "");
}
// Headers of 24-bit uncompressed images, without their pixels.
std::string bmpHeader(int width, int height) {
  return "BM" + le32(54) + le32(0) + le32(54) + le32(40) + le32(uint32_t(width)) + le32(uint32_t(height)) + le16(1) +
         le16(24) + le32(0) + le32(0) + le32(2835) + le32(2835) + le32(0) + le32(0);
}
std::string tgaHeader(int width, int height) {
  return std::string("\0\0\2", 3) + std::string(9, '\0') + le16(width) + le16(height) + std::string("\x18\0", 2);
}
std::string psdHeader(int width, int height) {
  return "8BPS" + be16(1) + std::string(6, '\0') + be16(3) + be32(uint32_t(height)) + be32(uint32_t(width)) + be16(8) +
         be16(3) + std::string(12, '\0') + be16(0);
}
std::string hdrHeader(int width, int height) {
  return "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + std::to_string(height) + " +X " + std::to_string(width) + "\n";
}

class DeclaredImageSizes : public TempDirTest {
 protected:
  std::string writeBytes(const std::string& name, const std::string& bytes) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  static std::string errorOf(const std::function<void()>& read) {
    try {
      read();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

}  // namespace

// A 4096 x 4096 image in a few bytes: decoders allocated it all (stb_image's decoders then read
// zeros past the end of the file, a black image, without an error).
TEST_F(DeclaredImageSizes, SizesTheFileCannotHoldAreErrorsBeforeDecoding) {
  const struct {
    const char* name;
    std::string bytes;
  } files[] = {{"big.png", pngHeader(4096, 4096)},
               {"big.bmp", bmpHeader(4096, 4096)},
               {"big.tga", tgaHeader(4096, 4096)},
               {"big.psd", psdHeader(4096, 4096)},
               {"big.hdr", hdrHeader(4096, 4096)}};
  for (const auto& file : files) {
    const std::string path = writeBytes(file.name, file.bytes);
    const std::string tail = "more than a file of " + std::to_string(file.bytes.size()) + " bytes can hold";
    expectContains(errorOf([&] { readImagePixels(path, true); }),
                   {file.name, "declares 4096 x 4096 pixels of 3 channels", tail.c_str()});
    if (file.name == std::string("big.png"))  // `fit --mask` and `montage` read PNG through libpng
      expectContains(errorOf([&] { readPNG(path); }), {file.name, "declares 4096 x 4096 pixels", tail.c_str()});
  }
}

// Found by the bitmap fuzzer: stb_image allocates a PNG chunk at its declared length before reading
// it (1.85 GB for an image of 9 x 5 pixels).
TEST_F(DeclaredImageSizes, PNGChunksLongerThanTheFileAreErrorsBeforeDecoding) {
  std::string png = pngHeader(9, 5);
  const size_t idat = png.find("IDAT") - 4;
  png.replace(idat, 4, be32(1852112923));
  expectContains(errorOf([&] { readImagePixels(writeBytes("chunk.png", png), false); }),
                 {"chunk.png: PNG chunk 'IDAT' at byte 33 declares 1852112923 bytes, but the file has"});
}

TEST_F(DeclaredImageSizes, FilesWithoutTheirPixelsAreErrorsNotBlackImages) {
  for (const auto& [name, bytes] : {std::pair<const char*, std::string>{"empty.bmp", bmpHeader(4, 4)},
                                    {"empty.tga", tgaHeader(4, 4)},
                                    {"empty.psd", psdHeader(4, 4)},
                                    {"short.bmp", bmpHeader(4, 4) + std::string(40, '\x7f')}})
    expectContains(errorOf([&, name = name, bytes = bytes] { readImagePixels(writeBytes(name, bytes), false); }),
                   {name, "the file ends before the pixels its header declares (4 x 4) are all there"});
  // A JPEG's headers without its scan (the start of scan replaced with the end of the image).
  std::ifstream in(std::string(COLUMBA_SOURCE_DIR) + "/fuzz/seeds/bitmap/baseline.jpg", std::ios::binary);
  std::string jpeg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NO_THROW(readImagePixels(writeBytes("whole.jpg", jpeg), false));
  jpeg = jpeg.substr(0, jpeg.find("\xff\xda")) + "\xff\xd9";
  expectContains(errorOf([&] { readImagePixels(writeBytes("noscan.jpg", jpeg), false); }),
                 {"noscan.jpg", "the JPEG image has no scan"});
  // Radiance HDR, flat (narrower than 8 pixels).
  expectContains(errorOf([&] { readImagePixels(writeBytes("flat.hdr", hdrHeader(4, 4) + "abcd"), false); }),
                 {"flat.hdr", "Radiance HDR scanline 0 of 4: the file ends 4 bytes into 64 bytes of pixels"});
}

// stb_image's run-length decoder loops forever on a literal of no bytes (a count of 0, which it
// also reads past the end of a file), and reads zeros past the end: the scanlines are checked
// before it decodes them.
TEST_F(DeclaredImageSizes, RunLengthHDRScanlinesAreCheckedBeforeDecoding) {
  const std::string header = hdrHeader(8, 2), start = std::string("\x02\x02\x00\x08", 4);
  const std::string fullChannel = std::string("\x88\x40", 2);  // a run of 8
  const std::string scanline = start + fullChannel + fullChannel + fullChannel + fullChannel;
  ASSERT_NO_THROW(readImagePixels(writeBytes("good.hdr", header + scanline + scanline), false));
  const struct {
    std::string pixels, expected;
  } cases[] = {
      {scanline + start + std::string("\x00", 1) + fullChannel, "scanline 1 of 2: a literal of no bytes"},
      {scanline + start + std::string("\x02\x11\x22", 3), "scanline 1 of 2: the file ends inside it"},
      {scanline + start + std::string("\x89\x40", 2), "scanline 1 of 2: a run of 9 bytes from byte 0 of channel 0"},
      {scanline + start + fullChannel + std::string("\x05", 1) + "abcde" + std::string("\x04", 1) + "abcd",
       "scanline 1 of 2: a literal of 4 bytes from byte 5 of channel 1, past its end"},
      {scanline + std::string("\x02\x02", 2), "scanline 1 of 2: the file ends before it"},
  };
  for (const auto& c : cases)
    expectContains(errorOf([&] { readLinearRGBImage(writeBytes("bad.hdr", header + c.pixels)); }),
                   {"bad.hdr", c.expected.c_str()});
}

// The size check counted pixels, not samples: an EXR of many spectral channels (or a float RGB
// one) declaring a window its file cannot fill was allocated, 4 bytes a sample, before OpenEXR
// found its pixels missing. readEXR is what compare, fit --target and envmaps read; bitmap
// textures read EXR through readImagePixels.
TEST_F(DeclaredImageSizes, EXRWindowsAreCheckedWithEveryChannel) {
  Image image(2, 2);
  for (int b = 0; b < 50; ++b) image.spectral.centres.push_back(400.0f + 6.0f * b);
  image.spectral.values.assign(4 * 50, 0.25f);
  const std::string spectral = (dir_ / "spectral.exr").string(), rgb = (dir_ / "rgb.exr").string();
  writeEXR(spectral, image);
  image.spectral = SpectralBands();
  writeEXR(rgb, image);
  // The data window made width x height (the display window stays: OpenEXR's own check).
  auto widen = [](const std::string& path, int32_t width, int32_t height) {
    std::string bytes;
    {
      std::ifstream in(path, std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string key("dataWindow\0box2i\0", 17);
    const size_t at = bytes.find(key);
    ASSERT_NE(at, std::string::npos);
    const int32_t window[4] = {0, 0, width - 1, height - 1};
    std::memcpy(&bytes[at + key.size() + 4], window, sizeof window);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  };
  widen(spectral, 20000, 8);
  widen(rgb, 1000, 1000);
  for (const auto& [path, declared] : {std::pair<std::string, const char*>{spectral, "20000 x 8 pixels of 53 channels"},
                                       {rgb, "1000 x 1000 pixels of 3 channels"}}) {
    const std::string expected = std::string("declares ") + declared + ", more than a file of";
    expectContains(errorOf([&, path = path] { readEXR(path); }), {path.c_str(), expected.c_str()});
    expectContains(errorOf([&, path = path] { readImagePixels(path, false); }), {path.c_str(), expected.c_str()});
  }
}

TEST(DeclaredImageSize, ImagesLargerThanTheMemoryBudgetOrEmptyAreErrors) {
  auto errorOf = [](const std::function<void()>& check) {
    try {
      check();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  expectContains(errorOf([] { checkImageMemory("big.exr", 65536, 65536, 3, 4); }),
                 {"big.exr: the header declares 65536 x 65536 pixels of 3 channels (48.0 GiB), more than the 4.0 GiB "
                  "an image may take"});
  expectContains(errorOf([] { checkDeclaredImageSize("big.png", 65536, 65536, 3, 4, uint64_t(1) << 40, 1.0); }),
                 {"big.png: the header declares 65536 x 65536 pixels of 3 channels (48.0 GiB)"});
  expectContains(errorOf([] { checkDeclaredImageSize("none.png", 0, 5, 3, 4, 100, 1.0); }),
                 {"none.png: the header declares 0 x 5 pixels of 3 channels: no samples"});
  expectContains(errorOf([] { checkDeclaredImageSize("small.png", 100, 100, 1, 4, 99, 100.0); }),
                 {"small.png: the header declares 100 x 100 pixels of 1 channels, more than a file of 99 bytes can "
                  "hold (at most 9900 samples)"});
  EXPECT_NO_THROW(checkDeclaredImageSize("fits.png", 100, 100, 1, 4, 100, 100.0));
}
