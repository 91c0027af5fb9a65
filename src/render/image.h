#pragma once
// Linear RGB float images and their files.
#include <string>
#include <vector>

namespace columba {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major, 3 floats per pixel, linear Rec.709
  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(size_t(w) * size_t(h) * 3, 0.0f) {}
  float* pixel(int x, int y) { return &rgb[(size_t(y) * width + x) * 3]; }
  const float* pixel(int x, int y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};

// Writers go through a temporary file renamed into place, so a failed or interrupted write
// never replaces a good file. They throw std::runtime_error naming the path on failure.
void writeEXR(const std::string& path, const Image& image);   // float32 RGB
void writePNG(const std::string& path, const Image& image);   // 8-bit sRGB, clamped
// Throws InputError naming the path if it cannot be read.
Image readEXR(const std::string& path);
// An 8-bit PNG (grey, RGB, with or without alpha) as linear values; throws InputError naming
// the path if it cannot be read.
Image readPNG(const std::string& path);
// The 8-bit sRGB encoding of a linear value, and the linear value of an sRGB-encoded one.
unsigned char toSRGB8(float linear);
float srgbToLinear(float encoded);

}  // namespace columba
