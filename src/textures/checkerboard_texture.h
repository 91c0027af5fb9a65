#pragma once
// Mitsuba's `checkerboard`: two values in alternating squares of half a unit of uv each.
#include <memory>
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class CheckerboardTexture : public Texture {
 public:
  CheckerboardTexture(SpectrumParameter color0, SpectrumParameter color1, Transform toUV)
      : color0_(std::move(color0)), color1_(std::move(color1)), toUV_(toUV) {}
  Spectrum evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const override;
  // A single value: color1 where inFirstColour, color0 elsewhere (Mitsuba's eval_1).
  float evalFloat(const TexturePoint& p) const override;
  // The luminance of evalSpectrum's colour, color0's where inFirstColour.
  float evalLuminance(const TexturePoint& p) const override;
  float mean() const override;

  // Whether `uv` (after to_uv) lies in a square of color0: the fractional parts of u and v are
  // both above 1/2 or both at most 1/2.
  bool inFirstColour(Vec2 uv) const;

 private:
  SpectrumParameter color0_, color1_;
  Transform toUV_;
};

// <texture type="checkerboard">: its parameters are in docs/reference/textures.md.
std::shared_ptr<Object> makeCheckerboardTexture(const Properties& props);

}  // namespace columba
