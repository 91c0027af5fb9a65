/*! plugin emitter envmap
Radiance at infinity from a latitude-longitude image (+y up, as Mitsuba lays it out), importance-sampled by pixel luminance: OpenEXR, Radiance HDR, PNG, JPEG, TGA, BMP and the other formats `bitmap` reads. Pixel colours become spectra as combinations of three smooth basis spectra, one per primary.
Mitsuba 3: the same parameters; `to_world` must be rigid (directions are sampled with their density in the map's own frame).
| parameter | type | default | meaning | Mitsuba 3 |
| filename | string | required | the image file | same |
| to_world | transform | identity | turns the map; rotation (or a mirror) only | — |
| scale | float | 1 | a factor on the radiance | same |
*/
#include "emitters/envmap_emitter.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include "core/error.h"
#include "io/image_file_reader.h"

namespace columba {

namespace {
Vec3 basisRGB(const SpectralDistribution& s) {
  Vec3 xyz(0, 0, 0);
  for (float l = kLambdaMin; l <= kLambdaMax; l += 1.0f) xyz += cieXYZ(l) * s.eval(l);
  return xyzToLinearRGB(xyz / cieYIntegral());
}

std::array<Vec3, 3> invert3x3(const std::array<Vec3, 3>& columns) {
  // Rows of the inverse are cross products of the columns divided by the determinant.
  const Vec3 &a = columns[0], &b = columns[1], &c = columns[2];
  float det = dot(a, cross(b, c));
  if (std::abs(det) < 1e-8f) throw std::runtime_error("degenerate spectral basis");
  return {cross(b, c) / det, cross(c, a) / det, cross(a, b) / det};
}
}  // namespace

EnvmapEmitter::EnvmapEmitter(Image image, float scale, const Transform& toWorld, const SourceLocation& where)
    : image_(std::move(image)), scale_(scale), toWorld_(toWorld) {
  std::vector<float> weights(size_t(image_.width) * image_.height);
  double total = 0.0;
  for (int y = 0; y < image_.height; ++y) {
    float sinTheta = std::sin(kPi * (y + 0.5f) / image_.height);
    for (int x = 0; x < image_.width; ++x) {
      const float* p = image_.pixel(x, y);
      // Named only when there is something to say: an environment map has millions of pixels.
      auto pixel = [&] { return "environment map pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")"; };
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw InputError(where, pixel() + " is not finite");
      float luminance = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
      float weight = std::max(luminance, 0.0f) * sinTheta + 1e-8f;
      if (!std::isfinite(weight))
        throw InputError(where, pixel() + " is too bright: its luminance overflows single precision");
      weights[size_t(y) * image_.width + x] = weight;
      total += weight;
    }
  }
  if (total > 0.5 * double(std::numeric_limits<float>::max()))
    throw InputError(where, "the environment map's total luminance overflows single precision");
  distribution_ = Distribution2D(weights, image_.width, image_.height);
  std::array<Vec3, 3> columns;
  for (int k = 0; k < 3; ++k) {
    Vec3 primary(k == 0, k == 1, k == 2);
    // Mitsuba's convention for emitted colours: the upsampled colour times D65.
    basis_[k] = SpectralDistribution::fromRGB(primary, true).timesD65();
    columns[k] = basisRGB(basis_[k]);
  }
  rgbToBasis_ = invert3x3(columns);
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
  int x = std::min(int(uv.x * image_.width), image_.width - 1);
  int y = std::min(int(uv.y * image_.height), image_.height - 1);
  const float* p = image_.pixel(x, y);
  Vec3 rgb(p[0], p[1], p[2]);
  Spectrum s;
  for (int i = 0; i < kSpectrumSamples; ++i) {
    float v = 0;
    for (int k = 0; k < 3; ++k) v += dot(rgbToBasis_[k], rgb) * basis_[k].eval(wl[i]);
    s[i] = std::max(v, 0.0f) * scale_;
  }
  return s;
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
