#include "render/splat_buffer.h"

#include <algorithm>
#include <cmath>

namespace columba {

SplatBuffer::SplatBuffer(const PixelRect& window, const ReconstructionFilter& filter)
    : window_(window),
      filter_(&filter),
      radius_(filter.radius()),
      sums_(size_t(window.width()) * size_t(window.height()) * 3, 0.0f) {}

void SplatBuffer::add(Vec2 filmPosition, const Vec3& rgb) {
  // Pixels whose centre x + 1/2 lies within the radius of the position.
  const int x0 = std::max(window_.x0, int(std::ceil(filmPosition.x - radius_ - 0.5f)));
  const int x1 = std::min(window_.x1 - 1, int(std::floor(filmPosition.x + radius_ - 0.5f)));
  const int y0 = std::max(window_.y0, int(std::ceil(filmPosition.y - radius_ - 0.5f)));
  const int y1 = std::min(window_.y1 - 1, int(std::floor(filmPosition.y + radius_ - 0.5f)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const float w = filter_->eval(Vec2(filmPosition.x - (float(x) + 0.5f), filmPosition.y - (float(y) + 0.5f)));
      if (w == 0.0f) continue;
      float* p = &sums_[(size_t(y - window_.y0) * size_t(window_.width()) + size_t(x - window_.x0)) * 3];
      p[0] += w * rgb.x;
      p[1] += w * rgb.y;
      p[2] += w * rgb.z;
    }
}

void SplatBuffer::clear() { std::fill(sums_.begin(), sums_.end(), 0.0f); }

}  // namespace columba
