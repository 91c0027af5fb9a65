#pragma once
// `hdrfilm`: the image size, the crop window rendered, the reconstruction filter and the visual
// system whose cone catches the image records beside RGB. Pixels are accumulated by the renderer.
#include <memory>
#include "core/properties.h"
#include "film/reconstruction_filter.h"
#include "io/image.h"
#include "vision/observer_response.h"

namespace columba {

class Film : public Object {
 public:
  // `crop` (empty: the whole film) must lie inside the film.
  Film(int width, int height, std::shared_ptr<ReconstructionFilter> filter, PixelRect crop = {},
       EXRColour colour = EXRColour::RGB, std::shared_ptr<const ObserverResponse> observer = nullptr)
      : width_(width),
        height_(height),
        crop_(crop.empty() ? PixelRect{0, 0, width, height} : crop),
        colour_(colour),
        filter_(std::move(filter)),
        observer_(std::move(observer)) {}
  // The full film, which the sensor's field of view spans.
  int width() const { return width_; }
  int height() const { return height_; }
  // The pixels rendered, as Mitsuba's crop window: the image holds just them, each the same as in
  // a render of the whole film. The whole film unless hdrfilm's crop_* parameters say otherwise.
  const PixelRect& crop() const { return crop_; }
  const ReconstructionFilter& filter() const { return *filter_; }
  // The colour channels of the image's EXR file (hdrfilm's pixel_format).
  EXRColour exrColour() const { return colour_; }
  // The visual system whose cone catches the image records (hdrfilm's `observer`); null for the
  // human observer of CIE 1931, whose colour is the RGB every image has.
  const ObserverResponse* observer() const { return observer_.get(); }
  // A black image of the crop's size, with the film's exrColour; if it cannot be allocated, throws std::runtime_error
  // saying how much memory it needs.
  Image makeImage() const;
  // The same film, uncropped, at another size (fitting a scene to a measured image of that size).
  std::shared_ptr<Film> resized(int width, int height) const {
    return std::make_shared<Film>(width, height, filter_, PixelRect{}, colour_, observer_);
  }

 private:
  int width_, height_;
  PixelRect crop_;
  EXRColour colour_;
  std::shared_ptr<ReconstructionFilter> filter_;
  std::shared_ptr<const ObserverResponse> observer_;
};

std::shared_ptr<Object> makeHDRFilm(const Properties& props);

}  // namespace columba
