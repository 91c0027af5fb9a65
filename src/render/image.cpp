#include "render/image.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <png.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>
#include "core/error.h"

namespace columba {

namespace {

void checkImage(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != size_t(image.width) * image.height * 3)
    throw std::runtime_error("cannot write '" + path + "': image of " + std::to_string(image.width) + " x " +
                             std::to_string(image.height) + " pixels holds " + std::to_string(image.rgb.size()) +
                             " values");
}

// Runs `write` on a temporary file beside `path`, then renames it into place; on failure the
// temporary file is removed and whatever was at `path` stays untouched.
void writeThroughTemporary(const std::string& path, const char* format,
                           const std::function<void(const std::string&)>& write) {
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  try {
    write(temporary);
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      throw std::runtime_error(std::string("cannot rename the temporary file into place: ") + std::strerror(errno));
  } catch (const std::exception& e) {
    std::remove(temporary.c_str());
    throw std::runtime_error(std::string("cannot write ") + format + " '" + path + "': " + e.what());
  }
}

void writeEXRFile(const std::string& file, const Image& image) {
  Imf::Header header(image.width, image.height);
  for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer frame;
  const size_t xStride = 3 * sizeof(float), yStride = xStride * size_t(image.width);
  const char* base = reinterpret_cast<const char*>(image.rgb.data());
  frame.insert("R", Imf::Slice(Imf::FLOAT, const_cast<char*>(base), xStride, yStride));
  frame.insert("G", Imf::Slice(Imf::FLOAT, const_cast<char*>(base + sizeof(float)), xStride, yStride));
  frame.insert("B", Imf::Slice(Imf::FLOAT, const_cast<char*>(base + 2 * sizeof(float)), xStride, yStride));

  // OpenEXR finishes the file in its destructor, which swallows errors: the stream's state
  // tells whether everything reached the disk.
  std::ofstream stream(file, std::ios::binary | std::ios::trunc);
  if (!stream) throw std::runtime_error(std::strerror(errno));
  {
    Imf::StdOFStream exrStream(stream, file.c_str());
    Imf::OutputFile out(exrStream, header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  }
  stream.close();
  if (!stream) throw std::runtime_error("write error");
}

void writePNGFile(const std::string& file, const Image& image) {
  std::vector<unsigned char> bytes(image.rgb.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = toSRGB8(image.rgb[i]);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = PNG_FORMAT_RGB;
  int ok = png_image_write_to_file(&png, file.c_str(), 0, bytes.data(), png_int_32(3 * image.width), nullptr);
  std::string message = png.message;
  png_image_free(&png);
  if (!ok) throw std::runtime_error(message);
}

}  // namespace

void writeEXR(const std::string& path, const Image& image) {
  checkImage(path, image);
  writeThroughTemporary(path, "EXR", [&](const std::string& file) { writeEXRFile(file, image); });
}

void writePNG(const std::string& path, const Image& image) {
  checkImage(path, image);
  writeThroughTemporary(path, "PNG", [&](const std::string& file) { writePNGFile(file, image); });
}

Image readEXR(const std::string& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imf::ChannelList& channels = file.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    if (!rgb && !channels.findChannel("Y"))
      throw InputError({path, 0}, "EXR image has neither R, G, B nor Y channels");
    const Imath::Box2i window = file.header().dataWindow();
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    const size_t xStride = 3 * sizeof(float), yStride = xStride * size_t(image.width);
    auto slice = [&](int c) { return Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, window, xStride, yStride); };
    Imf::FrameBuffer frame;
    if (rgb) {
      frame.insert("R", slice(0));
      frame.insert("G", slice(1));
      frame.insert("B", slice(2));
    } else {
      frame.insert("Y", slice(0));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    if (!rgb)  // grey
      for (size_t i = 0; i < image.rgb.size(); i += 3) image.rgb[i + 1] = image.rgb[i + 2] = image.rgb[i];
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError({path, 0}, std::string("cannot read EXR image: ") + e.what());
  }
}

Image readPNG(const std::string& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    std::string message = png.message;
    png_image_free(&png);
    throw InputError({path, 0}, "cannot read PNG image: " + message);
  }
  png.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> bytes(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, bytes.data(), 0, nullptr)) {
    std::string message = png.message;
    png_image_free(&png);
    throw InputError({path, 0}, "cannot read PNG image: " + message);
  }
  Image image(int(png.width), int(png.height));
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = srgbToLinear(bytes[i] / 255.0f);
  return image;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

unsigned char toSRGB8(float linear) {
  if (!(linear > 0.0f)) return 0;  // also NaN
  if (linear >= 1.0f) return 255;
  float encoded = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
  return static_cast<unsigned char>(std::lround(encoded * 255.0f));
}

}  // namespace columba
