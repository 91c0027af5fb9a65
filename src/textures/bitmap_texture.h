#pragma once
// Mitsuba's `bitmap` texture: an image file (io/image_file_reader.h) looked up at (u, v), with
// u across the image and v down it from the top row, as in Mitsuba (its OBJ loader flips v).
//
// As Mitsuba does in its spectral modes, a colour image is turned into one smooth spectrum per
// texel when it is loaded, and a bilinear lookup blends the four nearest texels' spectra at the
// path's wavelengths (texel centres at ((i + 1/2) / width, (j + 1/2) / height)). Grey images, and
// any image read with `raw`, keep their numbers.
#include <memory>
#include <string>
#include <vector>
#include "core/properties.h"
#include "io/image_file_reader.h"
#include "textures/texture.h"

namespace columba {

enum class TextureFilter { Bilinear, Nearest };
enum class TextureWrap { Repeat, Mirror, Clamp };

// The texel column (or row) that index `i` of a lookup reads, for an image `size` texels wide.
int wrapTexelIndex(int i, int size, TextureWrap wrap);

class BitmapTexture : public Texture {
 public:
  // `raw`: keep the file's numbers (no sRGB decoding was applied by the caller, no spectra).
  BitmapTexture(const PixelGrid& pixels, bool raw, TextureFilter filter, TextureWrap wrap, Transform toUV);
  Spectrum evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const override;
  float evalFloat(const TexturePoint& p) const override;
  Vec2 evalFloatGradient(const TexturePoint& p) const override;
  float mean() const override { return mean_; }

  int width() const { return width_; }
  int height() const { return height_; }
  // The colour as stored, for a colour image read with `raw` (a normal map).
  bool givesTriples() const override { return !rawRGB_.empty(); }
  Vec3 evalTriple(const TexturePoint& p) const override;

  // A grey image, or a colour image read without `raw`.
  bool givesSpectra() const override { return !spectra_.empty() || channels_ == 1; }

 private:
  // The texels a lookup at `uv` reads and their weights (one texel, weight 1, when nearest).
  struct Footprint {
    int count = 0;
    size_t texel[4] = {};
    float weight[4] = {};
    float tx = 0.0f, ty = 0.0f;  // bilinear: the position between the texel columns and rows
  };
  Footprint footprint(Vec2 uv) const;

  int width_, height_, channels_;
  TextureFilter filter_;
  TextureWrap wrap_;
  Transform toUV_;
  std::vector<float> values_;         // one number per texel: the grey value or the colour's luminance
  std::vector<RGBSpectrum> spectra_;  // one per texel for colour images read without `raw`
  std::vector<Vec3> rawRGB_;          // one per texel for colour images read with `raw`
  float mean_ = 0.0f;
};

// <texture type="bitmap">: its parameters are in docs/reference/textures.md.
std::shared_ptr<Object> makeBitmapTexture(const Properties& props);

}  // namespace columba
