#pragma once
// Light splatted onto a window of the film: RGB sums per pixel, each splat spread over the pixels
// within the filter's reach with the filter's value there. With the normalised filter f, a splat
// of value v at film position x adds f(x - c) v to the pixel centred at c: the expected sum is
// then the filter-weighted mean a camera sample of that pixel estimates.
#include <vector>
#include "core/vector.h"
#include "film/reconstruction_filter.h"
#include "io/image.h"

namespace columba {

class SplatBuffer {
 public:
  SplatBuffer(const PixelRect& window, const ReconstructionFilter& filter);
  // `filmPosition` in film pixels; pixels outside the window are left out.
  void add(Vec2 filmPosition, const Vec3& rgb);
  void clear();
  // Per pixel of the window, row by row, three values each.
  const std::vector<float>& sums() const { return sums_; }

 private:
  PixelRect window_;
  const ReconstructionFilter* filter_;
  float radius_;
  // Single precision: a buffer holds one block of light paths, few splats per pixel, and blocks
  // are summed in double precision.
  std::vector<float> sums_;
};

}  // namespace columba
