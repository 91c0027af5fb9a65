#pragma once
// The volume interface: a spectrum at every point of space (a medium's extinction or albedo),
// given over the unit cube [0, 1]^3 of its own space and placed in the scene by `to_world`; a
// value given directly to a medium fills all space instead.
#include <array>
#include <memory>
#include <optional>
#include "core/properties.h"
#include "core/ray.h"
#include "core/spectrum.h"
#include "core/transform.h"

namespace columba {

class Volume : public Object {
 public:
  // nullopt: the volume fills all space (its own space is the world's).
  explicit Volume(const std::optional<Transform>& toWorld)
      : toLocal_(toWorld ? toWorld->inverse() : Transform()), bounded_(toWorld.has_value()) {}
  // The value at world point p at the path's wavelengths.
  Spectrum eval(const Vec3& p, const Wavelengths& wl) const { return evalLocal(toLocal_.point(p), wl); }
  // No value at any wavelength exceeds it within the box lo to hi of the volume's own space (a
  // part of the unit cube, or any box for a volume filling space).
  virtual float maxValue(const Vec3& lo, const Vec3& hi) const = 0;
  // The largest value the scene gave for it (a grid's largest voxel value, a colour's largest
  // component), for parameters whose values are bounded.
  virtual float largestGivenValue() const = 0;
  // The cells per axis of a grid of such bounds over the unit cube that follows the volume's
  // variation (MajorantGrid); 1 for a volume of one value.
  virtual std::array<int, 3> majorantResolution() const { return {1, 1, 1}; }
  // From the scene to the volume's own space (the identity for a volume filling space).
  const Transform& worldToLocal() const { return toLocal_; }
  // The range of ray parameters (tmin, tmax clipped) within which the ray is inside the volume's
  // unit cube (all of it for a volume filling space), or nullopt where it misses it.
  std::optional<std::pair<float, float>> clip(const Ray& ray) const;

 protected:
  // The value at point p of the volume's own space (outside the unit cube as the volume says: a
  // grid clamps to it, or tiles space with its wrap mode repeat).
  virtual Spectrum evalLocal(const Vec3& p, const Wavelengths& wl) const = 0;

 private:
  Transform toLocal_;
  bool bounded_;
};

// A medium's volume parameter `name`: a nested <volume name="..."> or, as Mitsuba reads it, a
// <float>, <rgb> or <spectrum> given directly (a constant volume over all space), or `def`.
// `use` says how an RGB colour becomes a spectrum (SpectrumUse::NonNegative for an extinction,
// Fraction for an albedo, which is refused outside [0, 1] as a value or a volume).
std::shared_ptr<Volume> mediumVolume(const Properties& props, const std::string& name, float def, SpectrumUse use);

}  // namespace columba
