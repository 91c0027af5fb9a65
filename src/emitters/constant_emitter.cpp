/*! plugin emitter constant
The same radiance from every direction at infinity. Path tracing leaves it to the BSDF samples wherever the BSDF can draw every direction it scatters into.
Mitsuba 3: as Mitsuba 3's `constant`.
| parameter | type | default | meaning | Mitsuba 3 |
| radiance | spectrum | 1 | the radiance, as for `area` (a value or a colour is D65 of that luminance) | same |
*/
#include "emitters/constant_emitter.h"

#include "core/sampling.h"

namespace columba {

std::optional<EmitterSample> ConstantEmitter::sample(const Vec3&, Vec2 u, const Wavelengths& wl) const {
  EmitterSample s;
  s.direction = sampleUniformSphere(u);
  s.distance = std::numeric_limits<float>::infinity();
  s.radiance = radiance_.sample(wl);
  s.pdf = uniformSpherePdf();
  return s;
}

float ConstantEmitter::pdfDirection(const Vec3&) const { return uniformSpherePdf(); }

std::shared_ptr<Object> makeConstantEmitter(const Properties& props) {
  return std::make_shared<ConstantEmitter>(props.getSpectrum("radiance", 1.0f, SpectrumUse::Emission));
}

}  // namespace columba
