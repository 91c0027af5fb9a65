#include "emitters/ray_from_infinity.h"

#include "core/frame.h"
#include "core/sampling.h"

namespace columba {

std::optional<EmitterRaySample> rayFromInfinity(const EmitterSample& toLight, Vec2 uDisk, const SceneSphere& scene) {
  if (!(toLight.pdf > 0.0f) || !(scene.radius > 0.0f)) return std::nullopt;
  const Vec3 w = toLight.direction;
  const Frame frame = Frame::fromNormal(w);
  const Vec2 disk = sampleConcentricDisk(uDisk) * scene.radius;
  EmitterRaySample s;
  s.ray.o = scene.centre + w * scene.radius + frame.s * disk.x + frame.t * disk.y;
  s.ray.d = -w;
  s.weight = toLight.radiance * (kPi * scene.radius * scene.radius / toLight.pdf);
  return s;
}

}  // namespace columba
