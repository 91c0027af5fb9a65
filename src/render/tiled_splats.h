#pragma once
// Camera samples splatted tile by tile, so that an image is bit-identical for any thread count and
// any window of the film. Tiles lie on a grid fixed to the film; each splats the samples of its
// pixels into a buffer of its own, the tile grown by the filter's reach; a pixel's value sums the
// buffers in tile order, then divides by the pixel's filter mass on the film. A window renders the
// pixels within reach of it too, so each of its pixels gets the same additions, in the same order,
// as in a render of the whole film.
#include <tbb/parallel_for.h>

#include <memory>
#include <vector>
#include "film/filter_footprint.h"
#include "render/splat_buffer.h"

namespace columba {

class TiledSplats {
 public:
  static constexpr int kTileSize = 16;

  TiledSplats(const PixelRect& window, int filmWidth, int filmHeight, const FilterFootprint& footprint, int channels);
  int tileCount() const { return int(buffers_.size()); }
  const PixelRect& window() const { return window_; }
  // The pixels whose samples reach the window: it, and those within the filter's reach of it.
  const PixelRect& sources() const { return sources_; }
  // The pixels of `tile` whose samples reach the window: the ones to render.
  PixelRect tilePixels(int tile) const;
  // The tile's buffer, made on first use; used by one thread at a time.
  SplatBuffer& buffer(int tile);
  // Left out of the image (a tile whose rendering stopped early).
  void discard(int tile) { buffers_[size_t(tile)].reset(); }
  // Hands each row of the window's pixels, `channels` values per pixel, to `row(y, values)`, from
  // several threads at once.
  template <typename Row>
  void resolve(const Row& row) const;

 private:
  PixelRect window_, sources_;
  int filmWidth_, filmHeight_;
  int tilesX_ = 0, firstTileX_ = 0, firstTileY_ = 0;
  const FilterFootprint* footprint_;
  int channels_;
  std::vector<std::unique_ptr<SplatBuffer>> buffers_;

  // Row y's pixels: the buffers' sums in tile order, divided by each pixel's filter mass.
  void resolveRow(int y, double* values) const;
};

template <typename Row>
void TiledSplats::resolve(const Row& row) const {
  tbb::parallel_for(tbb::blocked_range<int>(window_.y0, window_.y1), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> values(size_t(window_.width()) * size_t(channels_));
    for (int y = rows.begin(); y != rows.end(); ++y) {
      resolveRow(y, values.data());
      row(y, values.data());
    }
  });
}

}  // namespace columba
