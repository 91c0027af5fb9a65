/*! plugin emitter area
Radiance leaving the front side of the shape it is nested in: the same everywhere, or a texture looked up at each point of the shape (its uv, or a mesh's attributes there). A texture's spectra are emitted as the texture gives them (a bitmap's white is an equal-energy light, not D65), as in Mitsuba 3, which hands a texture given to an emitter over unchanged; a value or a colour is an illuminant, times D65.
Mitsuba 3: as Mitsuba 3's `area`.
| parameter | type | default | meaning | Mitsuba 3 |
| radiance | spectrum or texture | 1 | the emitted radiance; a single value or an RGB colour is CIE D65 scaled to that luminance; not negative | same |
*/
#include "emitters/area_emitter.h"

#include <stdexcept>

#include "core/sampling.h"

namespace columba {

void AreaEmitter::attachTo(const Shape* shape) {
  if (shape_ && shape_ != shape) throw std::logic_error("an area emitter can belong to one shape only");
  shape_ = shape;
}

std::optional<EmitterSample> AreaEmitter::sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const {
  auto rs = shape_->sampleFrom(ref, u, radiance_.isTextured());
  if (!rs || !(rs->pdf > 0.0f)) return std::nullopt;
  EmitterSample s;
  Vec3 d = rs->p - ref;
  s.distance = length(d);
  s.direction = d / s.distance;
  s.radiance = radiance_.eval(rs->point, wl);
  s.pdf = rs->pdf;
  return s;
}

float AreaEmitter::pdfHit(const Vec3& ref, const SurfaceInteraction& hit) const { return shape_->pdfFrom(ref, hit); }

Spectrum AreaEmitter::radianceAt(const SurfaceInteraction& hit, const Vec3& toViewer, const Wavelengths& wl) const {
  return dot(hit.ng, toViewer) > 0.0f ? radiance_.eval(hit.texturePoint(), wl) : Spectrum(0.0f);
}

std::optional<PositionSample> AreaEmitter::samplePosition(Vec2 u) const {
  PositionSample ps = shape_->samplePosition(u, radiance_.isTextured());
  if (!(ps.pdfArea > 0.0f)) return std::nullopt;
  return ps;
}

// A point by area, then a direction by the cosine about the front's normal: the weight is
// L pi / pdfArea.
std::optional<EmitterRaySample> AreaEmitter::sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                                       const SceneSphere&) const {
  std::optional<PositionSample> ps = samplePosition(uPosition);
  if (!ps) return std::nullopt;
  const Vec3 local = sampleCosineHemisphere(uDirection);
  if (!(local.z > 0.0f)) return std::nullopt;
  EmitterRaySample s;
  s.ray = ps->interaction().spawnRay(Frame::fromNormal(ps->n).toWorld(local));
  s.weight = radiance_.eval(ps->point, wl) * (kPi / ps->pdfArea);
  return s;
}

std::shared_ptr<Object> makeAreaEmitter(const Properties& props) {
  return std::make_shared<AreaEmitter>(readSpectrumParameter(props, "radiance", 1.0f, SpectrumUse::Emission));
}

}  // namespace columba
