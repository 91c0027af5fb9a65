#pragma once
// The phase function interface: the angular distribution of light scattered in a medium.
// Directions point away from the scattering point: `wi` toward where the light comes from (the
// previous vertex, -ray.d) and `wo` toward where it goes, so forward scattering is wo = -wi.
// Phase functions are normalised over the sphere and do not depend on the wavelength, so one value
// serves every lane of a path.
#include <cmath>
#include <optional>
#include "core/frame.h"
#include "core/object.h"
#include "core/vector.h"

namespace columba {

struct PhaseSample {
  Vec3 wo;
  float pdf = 0.0f;  // solid-angle density of wo; for the phase functions here also their value
};

// The direction at scattering angle theta (its cosine `cosTheta`) from the light's direction of
// travel, -wi, at azimuth 2 pi uPhi around it: how each phase function here turns a drawn cos theta
// into wo.
// sinTheta given: where theta is too small for 1 - cos^2 in float (a phase function peaked within
// 1e-4 rad of forward).
inline Vec3 scatteredDirection(const Vec3& wi, float cosTheta, float sinTheta, float uPhi) {
  const float phi = kTwoPi * uPhi;
  return Frame::fromNormal(-wi).toWorld({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
}
inline Vec3 scatteredDirection(const Vec3& wi, float cosTheta, float uPhi) {
  return scatteredDirection(wi, cosTheta, std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta)), uPhi);
}

class PhaseFunction : public Object {
 public:
  // The phase function's value (per steradian) for light arriving from wi and leaving toward wo.
  virtual float eval(const Vec3& wi, const Vec3& wo) const = 0;
  // The density sample() draws wo with; equal to eval for phase functions sampled exactly.
  virtual float pdf(const Vec3& wi, const Vec3& wo) const { return eval(wi, wo); }
  // A direction drawn in proportion to eval from `u` in [0, 1)^2; nullopt where none can be drawn.
  virtual std::optional<PhaseSample> sample(const Vec3& wi, Vec2 u) const = 0;
};

}  // namespace columba
