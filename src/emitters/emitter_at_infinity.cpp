#include "emitters/emitter_at_infinity.h"

#include "core/frame.h"
#include "core/sampling.h"

namespace columba {

std::optional<EmitterRaySample> EmitterAtInfinity::sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                                             const SceneSphere& scene) const {
  std::optional<EmitterSample> toLight = sample(scene.centre, uDirection, wl);
  if (!toLight || !(toLight->pdf > 0.0f) || !(scene.radius > 0.0f)) return std::nullopt;
  const Vec3 w = toLight->direction;
  const Frame frame = Frame::fromNormal(w);
  const Vec2 disk = sampleConcentricDisk(uPosition) * scene.radius;
  EmitterRaySample s;
  s.ray.o = scene.centre + w * scene.radius + frame.s * disk.x + frame.t * disk.y;
  s.ray.d = -w;
  s.weight = toLight->radiance * (kPi * scene.radius * scene.radius / toLight->pdf);
  return s;
}

}  // namespace columba
