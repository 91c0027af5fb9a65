#include "film/film.h"

#include <fmt/format.h>

#include <new>
#include <stdexcept>

#include "film/gaussian_filter.h"

namespace columba {

Image Film::makeImage() const {
  try {
    return Image(width_, height_);
  } catch (const std::bad_alloc&) {
    double gib = double(width_) * double(height_) * 3 * sizeof(float) / double(1 << 30);
    throw std::runtime_error(
        fmt::format("the film of {} x {} pixels needs {:.1f} GiB of memory for its image, "
                    "which cannot be allocated",
                    width_, height_, gib));
  }
}

std::shared_ptr<Object> makeHDRFilm(const Properties& props) {
  int width = props.getInt("width", 768), height = props.getInt("height", 576);
  if (width <= 0 || width > 65536)
    throw props.error("width", "width must be in 1..65536, not " + std::to_string(width));
  if (height <= 0 || height > 65536)
    throw props.error("height", "height must be in 1..65536, not " + std::to_string(height));
  // Output is always linear float RGB; these are accepted for compatibility with Mitsuba scenes.
  std::string pixelFormat = props.getString("pixel_format", "rgb");
  if (pixelFormat != "rgb" && pixelFormat != "rgba")
    throw props.error("pixel_format", "only 'rgb' and 'rgba' are supported, not '" + pixelFormat + "'");
  std::string componentFormat = props.getString("component_format", "float16");
  if (componentFormat != "float16" && componentFormat != "float32")
    throw props.error("component_format", "only 'float16' and 'float32' are supported, not '" + componentFormat + "'");
  auto filter = props.child<ReconstructionFilter>();
  if (!filter)
    filter = makeDefaultPlugin<ReconstructionFilter>(makeGaussianFilter, "rfilter", "gaussian", props.location);
  return std::make_shared<Film>(width, height, std::move(filter));
}

}  // namespace columba
