/*! plugin emitter directional
Light from infinitely far away, travelling along `direction`.
Mitsuba 3: as Mitsuba 3's `directional`.
| parameter | type | default | meaning | Mitsuba 3 |
| direction | vector | (0, 0, 1) | the direction the light travels (before `to_world`); not zero | same |
| to_world | transform | identity | turns `direction` | same |
| irradiance | spectrum | 1 | the irradiance (W/m²/nm) on a surface facing the light; a value or a colour is D65 of that luminance | same |
*/
#include "emitters/directional_emitter.h"

namespace columba {

std::optional<EmitterSample> DirectionalEmitter::sample(const Vec3&, Vec2, const Wavelengths& wl) const {
  EmitterSample s;
  s.direction = -direction_;
  s.distance = std::numeric_limits<float>::infinity();
  s.radiance = irradiance_.sample(wl);
  s.pdf = 1.0f;
  return s;
}

std::shared_ptr<Object> makeDirectionalEmitter(const Properties& props) {
  Vec3 direction = props.getVector("direction", Vec3(0, 0, 1));
  if (props.has("to_world")) direction = props.getTransform("to_world").vector(direction);
  if (lengthSquared(direction) == 0.0f) throw props.error("direction", "the direction must not be zero");
  return std::make_shared<DirectionalEmitter>(direction, props.getSpectrum("irradiance", 1.0f, SpectrumUse::Emission));
}

}  // namespace columba
