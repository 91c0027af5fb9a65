#pragma once
// BSDF and emitter parameters that Mitsuba lets a scene texture: each holds either a constant
// (<float>, <rgb>, <spectrum>) or a texture, evaluated at the shading point.
#include <memory>
#include <string>
#include "core/properties.h"
#include "core/spectrum.h"
#include "textures/texture.h"

namespace columba {

class SpectrumParameter {
 public:
  SpectrumParameter(SpectralDistribution constant)  // NOLINT: a constant is the common case
      : constant_(std::move(constant)), constantLuminance_(constant_.luminance()) {}
  // A texture's spectra are taken as it gives them, for emitters too: Mitsuba 3 hands a texture
  // given to an emitter over unchanged (no D65), unlike a value or a colour.
  explicit SpectrumParameter(std::shared_ptr<const Texture> texture) : texture_(std::move(texture)) {}

  Spectrum eval(const TexturePoint& p, const Wavelengths& wl) const {
    return texture_ ? texture_->evalSpectrum(p, wl) : constant_.sample(wl);
  }
  // As a single number: the constant's luminance, or the texture's value as a number.
  float evalFloat(const TexturePoint& p) const { return texture_ ? texture_->evalFloat(p) : constantLuminance_; }
  // The luminance of eval's colour (Texture::evalLuminance).
  float evalLuminance(const TexturePoint& p) const {
    return texture_ ? texture_->evalLuminance(p) : constantLuminance_;
  }
  // Mean over the visible range (constant) or over the texture (its mean as a number).
  float meanValue() const { return texture_ ? texture_->mean() : constant_.meanValue(); }
  bool isTextured() const { return texture_ != nullptr; }

 private:
  SpectralDistribution constant_;
  float constantLuminance_ = 0.0f;
  std::shared_ptr<const Texture> texture_;
};

class FloatParameter {
 public:
  FloatParameter(float constant) : constant_(constant) {}  // NOLINT: a constant is the common case
  explicit FloatParameter(std::shared_ptr<const Texture> texture) : texture_(std::move(texture)) {}

  float eval(const TexturePoint& p) const { return texture_ ? texture_->evalFloat(p) : constant_; }
  float mean() const { return texture_ ? texture_->mean() : constant_; }
  bool isTextured() const { return texture_ != nullptr; }

 private:
  float constant_ = 0.0f;
  std::shared_ptr<const Texture> texture_;
};

// Parameter `name` of `props`: a nested or referenced <texture name="..."> if there is one, else
// the constant as Properties::getSpectrum / getFloat read it (`def` when absent). InputError when
// both a value and a texture are given. A texture is taken as given whatever `use` says (for an
// emitter too: no D65, as Mitsuba 3).
SpectrumParameter readSpectrumParameter(const Properties& props, const std::string& name, float def, SpectrumUse use);
FloatParameter readFloatParameter(const Properties& props, const std::string& name, float def);

}  // namespace columba
