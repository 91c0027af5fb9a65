/*! plugin emitter point
An isotropic point light.
Mitsuba 3: as Mitsuba 3's `point`; the projected texture of Mitsuba 3's point light is not read.
| parameter | type | default | meaning | Mitsuba 3 |
| position | point | (0, 0, 0) | where the light is (before `to_world`) | same |
| to_world | transform | identity | moves `position` | same |
| intensity | spectrum | 1 | the radiant intensity (W/sr/nm); a value or a colour is D65 of that luminance | same |
*/
#include "emitters/point_emitter.h"

#include "core/sampling.h"

namespace columba {

std::optional<EmitterSample> PointEmitter::sample(const Vec3& ref, Vec2, const Wavelengths& wl) const {
  Vec3 d = position_ - ref;
  float dist2 = lengthSquared(d);
  if (dist2 == 0.0f) return std::nullopt;
  EmitterSample s;
  s.distance = std::sqrt(dist2);
  s.direction = d / s.distance;
  s.radiance = intensity_.sample(wl) / dist2;
  s.pdf = 1.0f;
  return s;
}

// Uniform over the sphere of directions: the weight is I 4 pi.
std::optional<EmitterRaySample> PointEmitter::sampleRay(Vec2, Vec2 uDirection, const Wavelengths& wl,
                                                        const SceneSphere&) const {
  EmitterRaySample s;
  s.ray.o = position_;
  s.ray.d = sampleUniformSphere(uDirection);
  s.weight = intensity_.sample(wl) / uniformSpherePdf();
  return s;
}

std::shared_ptr<Object> makePointEmitter(const Properties& props) {
  Vec3 position = props.getVector("position", Vec3(0, 0, 0));
  if (props.has("to_world")) position = props.getTransform("to_world").point(position);
  return std::make_shared<PointEmitter>(position, props.getSpectrum("intensity", 1.0f, SpectrumUse::Emission));
}

}  // namespace columba
