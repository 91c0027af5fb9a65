#pragma once
// `hdrfilm`: the image size and the reconstruction filter. Pixels are accumulated by the renderer.
#include <memory>
#include "core/properties.h"
#include "film/reconstruction_filter.h"
#include "io/image.h"

namespace columba {

class Film : public Object {
 public:
  Film(int width, int height, std::shared_ptr<ReconstructionFilter> filter)
      : width_(width), height_(height), filter_(std::move(filter)) {}
  int width() const { return width_; }
  int height() const { return height_; }
  const ReconstructionFilter& filter() const { return *filter_; }
  // A black image of the film's size; if it cannot be allocated, throws std::runtime_error
  // saying how much memory it needs.
  Image makeImage() const;
  // The same film at another size (fitting a scene to a measured image of that size).
  std::shared_ptr<Film> resized(int width, int height) const { return std::make_shared<Film>(width, height, filter_); }

 private:
  int width_, height_;
  std::shared_ptr<ReconstructionFilter> filter_;
};

std::shared_ptr<Object> makeHDRFilm(const Properties& props);

}  // namespace columba
