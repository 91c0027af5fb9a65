#pragma once
// A texture: a BSDF parameter that varies over a surface, looked up by the surface's (u, v)
// coordinates (Mitsuba's `<texture>`). Every texture applies its own `to_uv` transform first.
#include "core/object.h"
#include "core/spectrum.h"
#include "core/transform.h"
#include "core/vector.h"

namespace columba {

class Texture : public Object {
 public:
  // The value at `uv` as a spectrum, at the path's wavelengths (colours, reflectances).
  virtual Spectrum evalSpectrum(Vec2 uv, const Wavelengths& wl) const = 0;
  // The value at `uv` as a single number (roughness, opacity, a blend weight): a grey texture's
  // value, a colour texture's luminance.
  virtual float evalFloat(Vec2 uv) const = 0;
  // The derivatives of evalFloat in u and in v (a bump map's slopes); zero where it is piecewise
  // constant.
  virtual Vec2 evalFloatGradient(Vec2 /*uv*/) const { return Vec2(0, 0); }
  // The mean over the unit square of uv, as a number: what a BSDF that chooses between its lobes
  // with fixed probabilities weighs them by (Mitsuba's Texture::mean).
  virtual float mean() const = 0;
  // False for a texture whose values are numbers that are not colours (a colour image read `raw`):
  // it cannot stand for a reflectance.
  virtual bool givesSpectra() const { return true; }
};

// The 2D part of a scene's `to_uv` transform (given as a 4x4 matrix): x and y of the matrix applied
// to the point (u, v, 0), as Mitsuba keeps rows and columns 0, 1 and 3.
Vec2 applyToUV(const Transform& toUV, Vec2 uv);

}  // namespace columba
