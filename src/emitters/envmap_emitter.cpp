/*! plugin emitter envmap
Radiance at infinity from a latitude-longitude image (+y up, as Mitsuba lays it out), importance-sampled by pixel luminance: OpenEXR, Radiance HDR, PNG, JPEG, TGA, BMP and the other formats `bitmap` reads. Each pixel's colour becomes a smooth spectrum times D65 (twice its largest component times the spectrum of the colour scaled to a largest component of 1/2), as Mitsuba 3 upsamples an environment map's pixels.
Mitsuba 3: the same parameters; `to_world` must be rigid (directions are sampled with their density in the map's own frame).
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the image file | same |
| to_world | transform | identity | turns the map; rotation (or a mirror) only | — |
| scale | float | 1 | a factor on the radiance | same |
*/
#include "emitters/envmap_emitter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include "core/error.h"
#include "core/illuminant.h"
#include "core/rgb_spectrum_table.h"
#include "io/image_file_reader.h"

namespace columba {

EnvmapEmitter::EnvmapEmitter(Image image, float scale, const Transform& toWorld, const SourceLocation& where)
    : width_(image.width), height_(image.height), toWorld_(toWorld) {
  std::vector<float> weights(size_t(width_) * height_);
  double total = 0.0;
  for (int y = 0; y < height_; ++y) {
    float sinTheta = std::sin(kPi * (y + 0.5f) / height_);
    for (int x = 0; x < width_; ++x) {
      const float* p = image.pixel(x, y);
      // Named only when there is something to say: an environment map has millions of pixels.
      auto pixel = [&] { return "environment map pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; };
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw InputError(where, pixel() + " is not finite");
      // Its spectrum is twice its largest component times a shape, which must stay finite.
      if (std::max({p[0], p[1], p[2]}) > 0.25f * std::numeric_limits<float>::max())
        throw InputError(where, pixel() + " is too bright: twice its largest component overflows single precision");
      float luminance = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
      float weight = std::max(luminance, 0.0f) * sinTheta + 1e-8f;
      if (!std::isfinite(weight))
        throw InputError(where, pixel() + " is too bright: its luminance overflows single precision");
      weights[size_t(y) * width_ + x] = weight;
      total += weight;
    }
  }
  if (total > 0.5 * double(std::numeric_limits<float>::max()))
    throw InputError(where, "the environment map's total luminance overflows single precision");
  distribution_ = Distribution2D(weights, width_, height_);
  // Each pixel's own spectrum, as Mitsuba gives each pixel (twice its largest component times the
  // spectrum of the colour scaled to a largest component of 1/2, times D65), from the table; the
  // map's scale goes into each spectrum's.
  spectra_ = tabulatedRGBSpectra(image.rgb.data(), size_t(width_) * height_);
  for (RGBSpectrum& s : spectra_) s.scale *= scale;
}

Vec2 EnvmapEmitter::directionToUV(const Vec3& worldDir) const {
  Vec3 d = normalize(toWorld_.inverse().vector(worldDir));
  float u = std::atan2(d.x, -d.z) * (0.5f * kInvPi);
  if (u < 0.0f) u += 1.0f;
  return {u, safeAcos(d.y) * kInvPi};
}

Vec3 EnvmapEmitter::uvToDirection(Vec2 uv) const {
  float phi = kTwoPi * uv.x, theta = kPi * uv.y;
  float s = std::sin(theta);
  return normalize(toWorld_.vector(Vec3(s * std::sin(phi), std::cos(theta), -s * std::cos(phi))));
}

Spectrum EnvmapEmitter::lookup(Vec2 uv, const Wavelengths& wl) const {
  int x = std::min(int(uv.x * width_), width_ - 1);
  int y = std::min(int(uv.y * height_), height_ - 1);
  const RGBSpectrum& r = spectra_[size_t(y) * width_ + x];
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) s[i] = r.eval(wl[i]);
  return s * d65(wl);
}

std::optional<EmitterSample> EnvmapEmitter::sample(const Vec3&, Vec2 u, const Wavelengths& wl) const {
  float pdfUV;
  Vec2 uv = distribution_.sample(u, &pdfUV);
  float sinTheta = std::sin(kPi * uv.y);
  if (pdfUV <= 0.0f || sinTheta <= 0.0f) return std::nullopt;
  EmitterSample s;
  s.direction = uvToDirection(uv);
  s.distance = std::numeric_limits<float>::infinity();
  s.radiance = lookup(uv, wl);
  s.pdf = pdfUV / (2.0f * kPi * kPi * sinTheta);
  return s;
}

Spectrum EnvmapEmitter::radianceFromDirection(const Vec3& d, const Wavelengths& wl) const {
  return lookup(directionToUV(d), wl);
}

float EnvmapEmitter::pdfDirection(const Vec3& d) const {
  Vec2 uv = directionToUV(d);
  float sinTheta = std::sin(kPi * uv.y);
  return sinTheta > 0.0f ? distribution_.pdf(uv) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

std::shared_ptr<Object> makeEnvmapEmitter(const Properties& props) {
  const std::string path = props.getPath("filename");
  Image image;
  try {
    image = readLinearRGBImage(path);
  } catch (const InputError& e) {
    throw props.error("filename", e.what());
  }
  // Directions are sampled in the map's own frame with their density there: a to_world that scales
  // or shears would change solid angles between the two.
  const Transform toWorld = props.getTransform("to_world");
  if (!toWorld.isRigid())
    throw props.error("to_world", "an envmap's to_world must not scale or shear (rotate it, or mirror it, only)");
  return std::make_shared<EnvmapEmitter>(std::move(image), props.getFloat("scale", 1.0f), toWorld,
                                         SourceLocation{path, 0});
}

}  // namespace columba
