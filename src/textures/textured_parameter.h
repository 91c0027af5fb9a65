#pragma once
// BSDF parameters that Mitsuba lets a scene texture: each holds either a constant (<float>,
// <rgb>, <spectrum>) or a texture, evaluated at the shading point's (u, v).
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
  explicit SpectrumParameter(std::shared_ptr<const Texture> texture) : texture_(std::move(texture)) {}

  Spectrum eval(Vec2 uv, const Wavelengths& wl) const {
    return texture_ ? texture_->evalSpectrum(uv, wl) : constant_.sample(wl);
  }
  // As a single number: the constant's luminance, or the texture's value as a number.
  float evalFloat(Vec2 uv) const { return texture_ ? texture_->evalFloat(uv) : constantLuminance_; }
  // Mean over the visible range (constant) or over the texture (its mean as a number).
  float meanValue() const { return texture_ ? texture_->mean() : constant_.meanValue(); }

 private:
  SpectralDistribution constant_;
  float constantLuminance_ = 0.0f;
  std::shared_ptr<const Texture> texture_;
};

class FloatParameter {
 public:
  FloatParameter(float constant) : constant_(constant) {}  // NOLINT: a constant is the common case
  explicit FloatParameter(std::shared_ptr<const Texture> texture) : texture_(std::move(texture)) {}

  float eval(Vec2 uv) const { return texture_ ? texture_->evalFloat(uv) : constant_; }
  float mean() const { return texture_ ? texture_->mean() : constant_; }
  bool isTextured() const { return texture_ != nullptr; }

 private:
  float constant_ = 0.0f;
  std::shared_ptr<const Texture> texture_;
};

// Parameter `name` of `props`: a nested or referenced <texture name="..."> if there is one, else
// the constant as Properties::getSpectrum / getFloat read it (`def` when absent). InputError when
// both a value and a texture are given.
SpectrumParameter readSpectrumParameter(const Properties& props, const std::string& name, float def, SpectrumUse use);
FloatParameter readFloatParameter(const Properties& props, const std::string& name, float def);

}  // namespace columba
