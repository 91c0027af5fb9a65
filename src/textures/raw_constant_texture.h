#pragma once
// Mitsuba's `rawconstant`: one number, or three, used as they are: no colour conversion and no
// range check. A single number is the same at every wavelength (a flat spectrum) and gives itself
// as a number; three numbers are not a colour, so they serve only where a texture's raw triple is
// read (a normal map), as in Mitsuba's spectral modes.
#include <memory>
#include "core/properties.h"
#include "textures/texture.h"

namespace columba {

class RawConstantTexture : public Texture {
 public:
  explicit RawConstantTexture(float value) : value_(value, value, value), channels_(1) {}
  explicit RawConstantTexture(Vec3 value) : value_(value), channels_(3) {}
  Spectrum evalSpectrum(const TexturePoint&, const Wavelengths&) const override { return Spectrum(value_.x); }
  float evalFloat(const TexturePoint&) const override { return value_.x; }
  float mean() const override { return (value_.x + value_.y + value_.z) / 3.0f; }
  bool givesSpectra() const override { return channels_ == 1; }
  bool givesNumbers() const override { return channels_ == 1; }
  bool givesTriples() const override { return true; }
  Vec3 evalTriple(const TexturePoint&) const override { return value_; }

 private:
  Vec3 value_;
  int channels_;
};

// <texture type="rawconstant">: its parameters are in docs/reference/textures.md.
std::shared_ptr<Object> makeRawConstantTexture(const Properties& props);

}  // namespace columba
