#include "io/image_file_reader.h"

#include <OpenImageIO/imageio.h>

#include "core/error.h"

namespace columba {

namespace {
// Larger images are refused rather than allocated: a corrupt header must not exhaust memory.
constexpr size_t kMaxPixels = size_t(1) << 28;

bool storedWithSRGBCurve(const OIIO::ImageSpec& spec) {
  const std::string space = spec.get_string_attribute("oiio:ColorSpace");
  if (space == "Linear" || space == "linear" || space == "lin_srgb" || space == "scene_linear") return false;
  return !spec.format.is_floating_point();
}
}  // namespace

PixelGrid readImagePixels(const std::string& path, bool decodeSRGB) {
  const SourceLocation where{path, 0};
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw InputError(where, "cannot read the image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  const int stored = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0) throw InputError(where, "the image is empty");
  if (size_t(spec.width) * size_t(spec.height) > kMaxPixels)
    throw InputError(where, "the image is too large (" + std::to_string(spec.width) + " x " +
                                std::to_string(spec.height) + " pixels)");
  // More channels are read when the first three are R, G and B (an EXR with further layers).
  const bool rgbFirst = stored >= 3 && spec.channelnames.size() >= 3 && spec.channelnames[0] == "R" &&
                        spec.channelnames[1] == "G" && spec.channelnames[2] == "B";
  if (stored < 1 || (stored > 4 && !rgbFirst))
    throw InputError(where, "the image has " + std::to_string(stored) +
                                " channels; grey, grey and alpha, RGB or RGBA are supported");
  PixelGrid grid;
  grid.width = spec.width;
  grid.height = spec.height;
  grid.channels = stored <= 2 ? 1 : 3;
  std::vector<float> all(size_t(grid.width) * size_t(grid.height) * size_t(stored));
  if (!input->read_image(0, 0, 0, stored, OIIO::TypeDesc::FLOAT, all.data()))
    throw InputError(where, "cannot read the image's pixels: " + input->geterror());
  const bool decode = decodeSRGB && storedWithSRGBCurve(spec);
  const size_t pixels = size_t(grid.width) * size_t(grid.height);
  grid.values.resize(pixels * size_t(grid.channels));
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < grid.channels; ++c) {
      float v = all[i * size_t(stored) + size_t(c)];
      grid.values[i * size_t(grid.channels) + size_t(c)] = decode ? srgbToLinear(v) : v;
    }
  return grid;
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
