#include "render/splat_buffer.h"

#include <algorithm>
#include <cmath>

namespace columba {

SplatBuffer::SplatBuffer(const PixelRect& rect, const FilterFootprint& footprint, int channels)
    : rect_(rect),
      footprint_(&footprint),
      channels_(channels),
      sums_(size_t(std::max(0, rect.width())) * size_t(std::max(0, rect.height())) * size_t(channels), 0.0) {}

namespace {
// The splat's loop, for a channel count known at compile time (kChannels > 0) or at run time. The
// products are taken in double precision, as the sums are kept.
template <int kChannels>
void addWeighted(double* sums, const PixelRect& rect, int channels, const FilterFootprint::AxisWeights& wx,
                 const FilterFootprint::AxisWeights& wy, const float* values) {
  const int n = kChannels > 0 ? kChannels : channels;
  const int x0 = std::max(rect.x0, wx.first), x1 = std::min(rect.x1, wx.first + wx.count);
  const int y0 = std::max(rect.y0, wy.first), y1 = std::min(rect.y1, wy.first + wy.count);
  const double* across = wx.weights + (x0 - wx.first);
  for (int y = y0; y < y1; ++y) {
    const double rowWeight = wy.weights[y - wy.first];
    double* p = sums + (size_t(y - rect.y0) * size_t(rect.width()) + size_t(x0 - rect.x0)) * size_t(n);
    for (int i = 0; i < x1 - x0; ++i, p += n) {
      const double w = rowWeight * across[i];
      for (int c = 0; c < n; ++c) p[c] += w * double(values[c]);
    }
  }
}
}  // namespace

void SplatBuffer::add(Vec2 filmPosition, const float* values) {
  const FilterFootprint::AxisWeights wx = footprint_->axisWeights(int(std::floor(filmPosition.x)), filmPosition.x);
  const FilterFootprint::AxisWeights wy = footprint_->axisWeights(int(std::floor(filmPosition.y)), filmPosition.y);
  if (channels_ == 3)
    addWeighted<3>(sums_.data(), rect_, channels_, wx, wy, values);
  else
    addWeighted<0>(sums_.data(), rect_, channels_, wx, wy, values);
}

void SplatBuffer::clear() { std::fill(sums_.begin(), sums_.end(), 0.0); }

}  // namespace columba
