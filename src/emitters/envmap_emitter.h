#pragma once
// `envmap`: radiance at infinity from a latitude-longitude EXR image (Mitsuba's layout: +y up),
// importance-sampled by pixel luminance.
#include <vector>
#include "core/distribution.h"
#include "core/properties.h"
#include "core/transform.h"
#include "emitters/emitter_at_infinity.h"
#include "io/image.h"

namespace columba {

class EnvmapEmitter : public EmitterAtInfinity {
 public:
  // Throws InputError at `where` (the image file) for a pixel that is not finite or too bright
  // to sample.
  EnvmapEmitter(Image image, float scale, const Transform& toWorld, const SourceLocation& where = {});
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  Spectrum radianceFromDirection(const Vec3& d, const Wavelengths& wl) const override;
  float pdfDirection(const Vec3& d) const override;

  bool isInfinite() const override { return true; }

 private:
  Vec2 directionToUV(const Vec3& worldDir) const;
  Vec3 uvToDirection(Vec2 uv) const;
  Spectrum lookup(Vec2 uv, const Wavelengths& wl) const;

  int width_, height_;
  Transform toWorld_;
  Distribution2D distribution_;
  // Each pixel's spectrum times the map's scale, without D65 (core/rgb_spectrum_table.h), in the
  // image's order.
  std::vector<RGBSpectrum> spectra_;
};

std::shared_ptr<Object> makeEnvmapEmitter(const Properties& props);

}  // namespace columba
