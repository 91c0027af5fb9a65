/*! plugin texture bitmap
An image texture: OpenEXR (read with OpenEXR) or PNG, JPEG, Radiance HDR, TGA, BMP, PNM, PSD and GIF (read with stb_image). v = 0 is the image's top row. 8- and 16-bit files are decoded from sRGB unless `raw`. Each colour texel becomes a smooth spectrum when the image is loaded, and a bilinear lookup blends the four texels' spectra.
Mitsuba 3: the same parameters and defaults; PFM files are not read.
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the image file | same |
| raw | boolean | false | the values as stored, without sRGB decoding or spectral upsampling (for normal maps and other data) | same |
| filter_type | string | `bilinear` | `bilinear` or `nearest` | same |
| wrap_mode | string | `repeat` | outside [0, 1]: `repeat`, `mirror` or `clamp` | same |
| to_uv | transform | identity | applied to the uv coordinates before the lookup | same |
| format | string | `variant` | the texels' storage precision: `variant` keeps them as float32, `fp16` (or `float16`) rounds each (linear, after sRGB decoding) to half precision, as Mitsuba stores it; anything else is an error | same; newer versions add `auto` and `uint8` |
*/
#include "textures/bitmap_texture.h"

#include <Imath/half.h>
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "textures/fitted_colours.h"

namespace columba {

namespace {
TextureFilter readFilter(const Properties& props) {
  const std::string name = props.getString("filter_type", "bilinear");
  if (name == "bilinear") return TextureFilter::Bilinear;
  if (name == "nearest") return TextureFilter::Nearest;
  throw props.error("filter_type", "unknown filter_type '" + name + "' (bilinear or nearest)");
}

TextureWrap readWrap(const Properties& props) {
  const std::string name = props.getString("wrap_mode", "repeat");
  if (name == "repeat") return TextureWrap::Repeat;
  if (name == "mirror") return TextureWrap::Mirror;
  if (name == "clamp") return TextureWrap::Clamp;
  throw props.error("wrap_mode", "unknown wrap_mode '" + name + "' (repeat, mirror or clamp)");
}
// Whether the texels are stored in half precision, as Mitsuba's `format` fp16 stores them: the
// values it looks up are rounded so.
bool readHalfStorage(const Properties& props) {
  const std::string name = props.getString("format", "variant");
  if (name == "variant") return false;
  if (name == "fp16" || name == "float16") return true;
  throw props.error("format", "unknown format '" + name + "' (variant or fp16)");
}
}  // namespace

int wrapTexelIndex(int i, int size, TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::Repeat: {
      int r = i % size;
      return r < 0 ? r + size : r;
    }
    case TextureWrap::Mirror: {
      // Period 2 * size: the image, then the image mirrored.
      int r = i % (2 * size);
      if (r < 0) r += 2 * size;
      return r < size ? r : 2 * size - 1 - r;
    }
    case TextureWrap::Clamp:
      return i < 0 ? 0 : (i >= size ? size - 1 : i);
  }
  return 0;
}

BitmapTexture::BitmapTexture(const PixelGrid& pixels, bool raw, TextureFilter filter, TextureWrap wrap, Transform toUV)
    : width_(pixels.width),
      height_(pixels.height),
      channels_(pixels.channels),
      filter_(filter),
      wrap_(wrap),
      toUV_(toUV) {
  const size_t count = size_t(width_) * size_t(height_);
  values_.resize(count);
  double sum = 0;
  if (channels_ == 1) {
    for (size_t i = 0; i < count; ++i) sum += values_[i] = pixels.values[i];
    mean_ = float(sum / double(count));
    return;
  }
  std::vector<Vec3> colours(count);
  for (size_t i = 0; i < count; ++i) {
    colours[i] = Vec3(pixels.values[3 * i], pixels.values[3 * i + 1], pixels.values[3 * i + 2]);
    values_[i] = linearRGBToXYZ(colours[i]).y;
  }
  if (raw) {
    rawRGB_ = std::move(colours);
    for (float v : values_) sum += v;
    mean_ = float(sum / double(count));
    return;
  }
  FittedColours fitted = fitColourSpectra(colours);
  spectra_ = std::move(fitted.spectra);
  mean_ = fitted.mean;
}

BitmapTexture::Footprint BitmapTexture::footprint(Vec2 uvIn) const {
  const Vec2 uv = applyToUV(toUV_, uvIn);
  Footprint f;
  auto texel = [&](int x, int y) {
    return size_t(wrapTexelIndex(y, height_, wrap_)) * size_t(width_) + size_t(wrapTexelIndex(x, width_, wrap_));
  };
  if (filter_ == TextureFilter::Nearest) {
    f.count = 1;
    f.texel[0] = texel(int(std::floor(uv.x * float(width_))), int(std::floor(uv.y * float(height_))));
    f.weight[0] = 1.0f;
    return f;
  }
  const float x = uv.x * float(width_) - 0.5f, y = uv.y * float(height_) - 0.5f;
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float tx = x - x0, ty = y - y0;
  const int ix = int(x0), iy = int(y0);
  f.count = 4;
  f.tx = tx;
  f.ty = ty;
  f.texel[0] = texel(ix, iy);
  f.texel[1] = texel(ix + 1, iy);
  f.texel[2] = texel(ix, iy + 1);
  f.texel[3] = texel(ix + 1, iy + 1);
  f.weight[0] = (1.0f - tx) * (1.0f - ty);
  f.weight[1] = tx * (1.0f - ty);
  f.weight[2] = (1.0f - tx) * ty;
  f.weight[3] = tx * ty;
  return f;
}

Spectrum BitmapTexture::evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const {
  if (spectra_.empty()) return Spectrum(evalFloat(p));  // a grey image
  const Footprint f = footprint(p.uv);
  Spectrum result(0.0f);
  for (int k = 0; k < f.count; ++k) {
    const RGBSpectrum& s = spectra_[f.texel[k]];
    Spectrum texel;
    for (int i = 0; i < kSpectrumSamples; ++i) texel[i] = s.eval(wl[i]);
    result += texel * f.weight[k];
  }
  return result;
}

float BitmapTexture::evalFloat(const TexturePoint& p) const {
  const Footprint f = footprint(p.uv);
  float result = 0.0f;
  for (int k = 0; k < f.count; ++k) result += values_[f.texel[k]] * f.weight[k];
  return result;
}

Vec2 BitmapTexture::evalFloatGradient(const TexturePoint& p) const {
  if (filter_ == TextureFilter::Nearest) return Vec2(0, 0);
  const Footprint f = footprint(p.uv);
  const float v00 = values_[f.texel[0]], v10 = values_[f.texel[1]], v01 = values_[f.texel[2]],
              v11 = values_[f.texel[3]];
  // Slopes per unit of the looked-up coordinates, then through to_uv's linear part (its transpose).
  const float dx = float(width_) * ((1.0f - f.ty) * (v10 - v00) + f.ty * (v11 - v01));
  const float dy = float(height_) * ((1.0f - f.tx) * (v01 - v00) + f.tx * (v11 - v10));
  const auto& m = toUV_.matrix().m;
  return Vec2(float(m[0][0] * dx + m[1][0] * dy), float(m[0][1] * dx + m[1][1] * dy));
}

Vec3 BitmapTexture::evalTriple(const TexturePoint& p) const {
  if (rawRGB_.empty()) throw std::logic_error("evalTriple: the texture holds no raw colours");
  const Footprint f = footprint(p.uv);
  Vec3 result(0, 0, 0);
  for (int k = 0; k < f.count; ++k) result += rawRGB_[f.texel[k]] * f.weight[k];
  return result;
}

std::shared_ptr<Object> makeBitmapTexture(const Properties& props) {
  const std::string path = props.getPath("filename");
  const bool raw = props.getBool("raw", false);
  PixelGrid pixels;
  try {
    pixels = readImagePixels(path, !raw);
  } catch (const InputError& e) {
    throw props.error("filename", e.what());
  }
  if (readHalfStorage(props))
    for (size_t i = 0; i < pixels.values.size(); ++i) {
      // Beyond half's largest value a texel would become infinite, and its light lost.
      if (std::abs(pixels.values[i]) > float(HALF_MAX)) {
        const size_t texel = i / size_t(pixels.channels);
        throw props.error("format", fmt::format("'{}': the texel at x {}, y {}, channel {} is {:g}, beyond half "
                                                "precision's largest value {:g}: give format 'variant' to keep it",
                                                path, texel % size_t(pixels.width), texel / size_t(pixels.width),
                                                i % size_t(pixels.channels), pixels.values[i], float(HALF_MAX)));
      }
      pixels.values[i] = float(Imath::half(pixels.values[i]));
    }
  return std::make_shared<BitmapTexture>(pixels, raw, readFilter(props), readWrap(props), props.getTransform("to_uv"));
}

}  // namespace columba
