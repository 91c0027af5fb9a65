/*! plugin film hdrfilm
The film: the image as an OpenEXR file of float32 values (and a PNG preview). Samples are splatted, weighted by the reconstruction filter, over every pixel the filter reaches. It holds one nested `rfilter` (default: `gaussian`). The film records XYZ, converted to linear Rec. 709 (sRGB primaries) with the plain matrix, without white balance.
Mitsuba 3: the same size and crop parameters and defaults; only OpenEXR is written, always as float32; the alpha pixel formats are written without alpha.
| parameter | type | default | meaning | Mitsuba 3 |
| width | integer | 768 | the image width in pixels, 1 to 65536 | same |
| height | integer | 576 | the image height in pixels, 1 to 65536 | same |
| crop_offset_x | integer | 0 | the crop window's left column, inside the film; only the window is rendered, each pixel as in the full render, and a split render's parts divide the window | same |
| crop_offset_y | integer | 0 | the crop window's top row, inside the film | same |
| crop_width | integer | `width` | the crop window's width; it must fit inside the film | same |
| crop_height | integer | `height` | the crop window's height; it must fit inside the film | same |
| file_format | string | `openexr` | `openexr` or `exr`; anything else is an error | also `rgbe`, `pfm` and others |
| pixel_format | string | `rgb` | the EXR's channels: `rgb`, `luminance` (Y) or `xyz` (CIE XYZ); `rgba`, `luminance_alpha` and `xyza` are written without alpha, with a warning naming the line, as no coverage is computed. The pieces of a split render and their merge stay RGB | alpha formats write coverage |
| component_format | string | `float16` | `float16` or `float32`, accepted; the values are always written as float32 | chooses the stored precision |
| sample_border | boolean | `false` | `false` only: a pixel within the filter's reach of the film's edge is filtered from samples on the film (those of the crop window's neighbours too); `true`, which adds samples from outside the film, is not implemented and warns naming the line | `true` also samples a border as wide as the filter outside the crop window |
| observer | string | `cie1931` | the visual system the image is seen by: `cie1931` (the human observer; RGB only), a built-in bird's (`bluetit`, `avg.uv`, `avg.v`: docs/vision.md) or a bird's `FILE.csv`: a table of its sensitivities (a `wl` column and columns named after the cones) or of its cones' published parameters (a `cone` column, `lambda_max`, `droplet`, ...; docs/vision.md, "Observers from a table"). A bird's film records each cone's quantum catch beside RGB, as EXR channels named after the cones (`VS`, `SWS`, `MWS`, `LWS`, ...), draws wavelengths over 300-830 nm in proportion to the cones' sensitivities, and writes a false-colour PNG (red LWS, green MWS, blue SWS, the UV/violet cone as magenta) | not in Mitsuba 3 |
| adaptation | string | `d65` | with a bird's `observer`: the white the catches are relative to (von Kries): `d65` (a white diffuse surface under a white Columba emitter catches 1 in every cone) or `none` (absolute catches, also the adaptation to an equal-quantum white) | not in Mitsuba 3 |
*/
#include "film/film.h"

#include <fmt/format.h>

#include <new>
#include <stdexcept>

#include "film/gaussian_filter.h"
#include "vision/observer_table.h"

namespace columba {

Image Film::makeImage() const {
  try {
    Image image(crop_.width(), crop_.height());
    image.exrColour = colour_;
    if (observer_) {
      image.cones.names = observer_->channels();
      image.cones.values.assign(image.rgb.size() / 3 * image.cones.count(), 0.0f);
    }
    return image;
  } catch (const std::bad_alloc&) {
    double gib = double(crop_.width()) * double(crop_.height()) * 3 * sizeof(float) / double(1 << 30);
    throw std::runtime_error(
        fmt::format("the film of {} x {} pixels needs {:.1f} GiB of memory for its image, "
                    "which cannot be allocated",
                    crop_.width(), crop_.height(), gib));
  }
}

std::shared_ptr<Object> makeHDRFilm(const Properties& props) {
  int width = props.getInt("width", 768), height = props.getInt("height", 576);
  if (width <= 0 || width > 65536)
    throw props.error("width", "width must be in 1..65536, not " + std::to_string(width));
  if (height <= 0 || height > 65536)
    throw props.error("height", "height must be in 1..65536, not " + std::to_string(height));
  // Mitsuba's crop window: its size defaults to the whole film whatever the offset, and it must
  // fit inside the film.
  const int offsetX = props.getInt("crop_offset_x", 0), offsetY = props.getInt("crop_offset_y", 0);
  const int cropWidth = props.getInt("crop_width", width), cropHeight = props.getInt("crop_height", height);
  if (offsetX < 0 || offsetX >= width)
    throw props.error(
        "crop_offset_x",
        fmt::format("crop_offset_x must be in 0..{} (the film is {} pixels wide), not {}", width - 1, width, offsetX));
  if (offsetY < 0 || offsetY >= height)
    throw props.error("crop_offset_y",
                      fmt::format("crop_offset_y must be in 0..{} (the film is {} pixels high), not {}", height - 1,
                                  height, offsetY));
  if (cropWidth <= 0 || cropWidth > width - offsetX)
    throw props.error("crop_width",
                      fmt::format("crop_width must be in 1..{} (crop_offset_x {} on a film {} pixels wide), not {}",
                                  width - offsetX, offsetX, width, cropWidth));
  if (cropHeight <= 0 || cropHeight > height - offsetY)
    throw props.error("crop_height",
                      fmt::format("crop_height must be in 1..{} (crop_offset_y {} on a film {} pixels high), not {}",
                                  height - offsetY, offsetY, height, cropHeight));
  // The output is an EXR file of float32 values; Mitsuba's colour choices are honoured. Those with
  // an alpha channel are written without it, with a warning: Columba computes no coverage, and
  // refusing them would stop many exported scenes (rgba is a common choice) from loading.
  const std::string fileFormat = props.getString("file_format", "openexr");
  if (fileFormat != "openexr" && fileFormat != "exr")
    throw props.error("file_format", "file_format must be 'openexr' (or 'exr'), not '" + fileFormat +
                                         "': Columba writes OpenEXR files (and PNG previews)");
  const std::string pixelFormat = props.getString("pixel_format", "rgb");
  EXRColour colour;
  if (pixelFormat == "rgb") {
    colour = EXRColour::RGB;
  } else if (pixelFormat == "luminance") {
    colour = EXRColour::Luminance;
  } else if (pixelFormat == "xyz") {
    colour = EXRColour::XYZ;
  } else if (pixelFormat == "rgba" || pixelFormat == "luminance_alpha" || pixelFormat == "xyza") {
    const std::string withoutAlpha = pixelFormat == "rgba" ? "rgb" : pixelFormat == "xyza" ? "xyz" : "luminance";
    colour = pixelFormat == "rgba" ? EXRColour::RGB : pixelFormat == "xyza" ? EXRColour::XYZ : EXRColour::Luminance;
    warn(props.locationOf("pixel_format"), "pixel_format '" + pixelFormat +
                                               "': Columba computes no alpha channel; the image is written as '" +
                                               withoutAlpha + "'");
  } else {
    throw props.error("pixel_format",
                      "pixel_format must be rgb, luminance or xyz (or rgba, luminance_alpha and xyza, written "
                      "without their alpha channel), not '" +
                          pixelFormat + "'");
  }
  std::string componentFormat = props.getString("component_format", "float16");
  if (componentFormat != "float16" && componentFormat != "float32")
    throw props.error("component_format", "only 'float16' and 'float32' are supported, not '" + componentFormat + "'");
  // Columba samples the pixels within the filter's reach of the crop window, but none off the film,
  // so sample_border true would change the film's edge pixels (with any filter wider than a box).
  if (props.getBool("sample_border", false))
    warn(props.locationOf("sample_border"),
         "sample_border true is not supported: pixels near the film's edge are filtered from samples on the "
         "film only, as with false");
  std::shared_ptr<const ObserverResponse> observer;
  const std::string observerName = props.getString("observer", "cie1931");
  if (observerName != "cie1931") {
    Adaptation adaptation;
    try {
      adaptation = adaptationNamed(props.getString("adaptation", "d65"));
    } catch (const std::invalid_argument& e) {
      throw props.error("adaptation", e.what());
    }
    try {
      const Observer o = namesObserverTable(observerName) ? readObserverTableFile(props.getPath("observer"))
                                                          : observerNamedOrTabulated(observerName);
      observer = std::make_shared<ObserverResponse>(o, adaptation);
    } catch (const std::invalid_argument& e) {
      throw props.error("observer", std::string(e.what()) + "; cie1931 is the human observer");
    }
  } else if (props.has("adaptation")) {
    warn(props.locationOf("adaptation"),
         "adaptation '" + props.getString("adaptation", "") +
             "' has no effect: the film's observer is cie1931, whose RGB has no cone catches to adapt");
  }
  auto filter = props.child<ReconstructionFilter>();
  if (!filter)
    filter = makeDefaultPlugin<ReconstructionFilter>(makeGaussianFilter, "rfilter", "gaussian", props.location);
  return std::make_shared<Film>(width, height, std::move(filter),
                                PixelRect{offsetX, offsetY, offsetX + cropWidth, offsetY + cropHeight}, colour,
                                std::move(observer));
}

}  // namespace columba
