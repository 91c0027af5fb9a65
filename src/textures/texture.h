#pragma once
// A texture: a BSDF or emitter parameter that varies over a surface (Mitsuba's `<texture>`),
// looked up at a TexturePoint: the surface's (u, v) and, on meshes with per-vertex or per-face
// values, where in which triangle. Every texture applies its own `to_uv` transform first.
#include "core/object.h"
#include "core/spectrum.h"
#include "core/transform.h"
#include "core/vector.h"
#include "textures/texture_point.h"

namespace columba {

class Texture : public Object {
 public:
  // The value at `p` as a spectrum, at the path's wavelengths (colours, reflectances).
  virtual Spectrum evalSpectrum(const TexturePoint& p, const Wavelengths& wl) const = 0;
  // The value at `p` as a single number (roughness, opacity, a blend weight): a grey texture's
  // value, a colour texture's luminance.
  virtual float evalFloat(const TexturePoint& p) const = 0;
  // The luminance of evalSpectrum's colour at `p` (the principled BSDFs' tint divides by it, as
  // Mitsuba's does by the luminance of its colour): evalFloat's value for every texture but the
  // checkerboard, whose single values take its colours the other way round.
  virtual float evalLuminance(const TexturePoint& p) const { return evalFloat(p); }
  // The derivatives of evalFloat in u and in v (a bump map's slopes); zero where it is piecewise
  // constant.
  virtual Vec2 evalFloatGradient(const TexturePoint& /*p*/) const { return Vec2(0, 0); }
  // The mean over the unit square of uv, as a number: what a BSDF that chooses between its lobes
  // with fixed probabilities weighs them by (Mitsuba's Texture::mean).
  virtual float mean() const = 0;
  // False for a texture whose values are numbers that are not colours (a colour image read `raw`):
  // it cannot stand for a reflectance.
  virtual bool givesSpectra() const { return true; }
  // False for a texture of three numbers that are not a colour (a 3-component rawconstant): it
  // cannot stand for a single number either.
  virtual bool givesNumbers() const { return true; }
  // Whether evalTriple gives three numbers as stored, with no colour conversion (Mitsuba's eval_3
  // of a raw bitmap, a rawconstant or a mesh attribute): what a normal map reads.
  virtual bool givesTriples() const { return false; }
  virtual Vec3 evalTriple(const TexturePoint& p) const;
};

// The 2D part of a scene's `to_uv` transform (given as a 4x4 matrix): x and y of the matrix applied
// to the point (u, v, 0), as Mitsuba keeps rows and columns 0, 1 and 3.
Vec2 applyToUV(const Transform& toUV, Vec2 uv);

}  // namespace columba
