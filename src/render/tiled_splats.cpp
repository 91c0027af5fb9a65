#include "render/tiled_splats.h"

#include <algorithm>

namespace columba {

namespace {
PixelRect grown(const PixelRect& r, int by) { return {r.x0 - by, r.y0 - by, r.x1 + by, r.y1 + by}; }
PixelRect intersection(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}
}  // namespace

TiledSplats::TiledSplats(const PixelRect& window, int filmWidth, int filmHeight, const FilterFootprint& footprint,
                         int channels)
    : window_(window),
      sources_(intersection(grown(window, footprint.reach()), PixelRect{0, 0, filmWidth, filmHeight})),
      filmWidth_(filmWidth),
      filmHeight_(filmHeight),
      footprint_(&footprint),
      channels_(channels) {
  // The sources lie on the film, so their coordinates are not negative.
  firstTileX_ = sources_.x0 / kTileSize;
  firstTileY_ = sources_.y0 / kTileSize;
  tilesX_ = (sources_.x1 - 1) / kTileSize - firstTileX_ + 1;
  const int tilesY = (sources_.y1 - 1) / kTileSize - firstTileY_ + 1;
  buffers_.resize(sources_.empty() ? 0 : size_t(tilesX_) * size_t(tilesY));
}

PixelRect TiledSplats::tilePixels(int tile) const {
  const int tx = firstTileX_ + tile % tilesX_, ty = firstTileY_ + tile / tilesX_;
  return intersection({tx * kTileSize, ty * kTileSize, (tx + 1) * kTileSize, (ty + 1) * kTileSize}, sources_);
}

SplatBuffer& TiledSplats::buffer(int tile) {
  std::unique_ptr<SplatBuffer>& b = buffers_[size_t(tile)];
  if (!b)
    b = std::make_unique<SplatBuffer>(intersection(grown(tilePixels(tile), footprint_->reach()), window_), *footprint_,
                                      channels_);
  return *b;
}

void TiledSplats::resolveRow(int y, double* values) const {
  const size_t n = size_t(channels_);
  std::fill(values, values + size_t(window_.width()) * n, 0.0);
  for (const std::unique_ptr<SplatBuffer>& b : buffers_) {
    if (!b) continue;
    const PixelRect& r = b->rect();
    if (y < r.y0 || y >= r.y1) continue;
    const double* sums = &b->sums()[size_t(y - r.y0) * size_t(r.width()) * n];
    double* out = values + size_t(r.x0 - window_.x0) * n;
    for (size_t i = 0; i < size_t(r.width()) * n; ++i) out[i] += sums[i];
  }
  const double massY = footprint_->massWithin(y, filmHeight_);
  for (int x = window_.x0; x < window_.x1; ++x) {
    const double mass = footprint_->massWithin(x, filmWidth_) * massY;
    double* p = values + size_t(x - window_.x0) * n;
    for (size_t c = 0; c < n; ++c) p[c] = mass > 0.0 ? p[c] / mass : 0.0;
  }
}

}  // namespace columba
