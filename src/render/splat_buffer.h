#pragma once
// Samples splatted onto a rectangle of the film's pixels: per pixel, `channels` sums, each sample
// adding its values times its weight for the pixel (film/filter_footprint.h). Pixels outside the
// rectangle are left out.
#include <vector>
#include "core/vector.h"
#include "film/filter_footprint.h"
#include "io/image.h"

namespace columba {

class SplatBuffer {
 public:
  SplatBuffer(const PixelRect& rect, const FilterFootprint& footprint, int channels = 3);
  const PixelRect& rect() const { return rect_; }
  int channels() const { return channels_; }
  // A sample at `filmPosition` (film pixels) with `channels()` values.
  void add(Vec2 filmPosition, const float* values);
  void add(Vec2 filmPosition, const Vec3& rgb) {
    const float values[3] = {rgb.x, rgb.y, rgb.z};
    add(filmPosition, values);
  }
  void clear();
  // Per pixel of the rectangle, row by row, `channels()` values each.
  const std::vector<double>& sums() const { return sums_; }

 private:
  PixelRect rect_;
  const FilterFootprint* footprint_;
  int channels_;
  // Double precision, as buffers are summed: renders of sample ranges then merge into the render
  // of all of them to float32 round-off.
  std::vector<double> sums_;
};

}  // namespace columba
