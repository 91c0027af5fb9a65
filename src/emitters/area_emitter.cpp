#include "emitters/area_emitter.h"

#include <stdexcept>

namespace columba {

void AreaEmitter::attachTo(const Shape* shape) {
  if (shape_ && shape_ != shape) throw std::logic_error("an area emitter can belong to one shape only");
  shape_ = shape;
}

std::optional<EmitterSample> AreaEmitter::sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const {
  PositionSample ps = shape_->samplePosition(u);
  Vec3 d = ps.p - ref;
  float dist2 = lengthSquared(d);
  if (dist2 == 0.0f) return std::nullopt;
  float dist = std::sqrt(dist2);
  d = d / dist;
  float cosLight = -dot(ps.n, d);
  if (cosLight <= 0.0f) return std::nullopt;  // the back of a one-sided emitter
  EmitterSample s;
  s.direction = d;
  s.distance = dist;
  s.radiance = radiance_.sample(wl);
  s.pdf = ps.pdfArea * dist2 / cosLight;
  return s;
}

float AreaEmitter::pdfHit(const Vec3& ref, const SurfaceInteraction& hit) const {
  Vec3 d = hit.p - ref;
  float dist2 = lengthSquared(d);
  float cosLight = -dot(hit.ng, d) / std::sqrt(dist2);
  if (cosLight <= 0.0f) return 0.0f;
  return dist2 / (cosLight * shape_->surfaceArea());
}

Spectrum AreaEmitter::radianceAt(const SurfaceInteraction& hit, const Vec3& toViewer, const Wavelengths& wl) const {
  return dot(hit.ng, toViewer) > 0.0f ? radiance_.sample(wl) : Spectrum(0.0f);
}

std::shared_ptr<Object> makeAreaEmitter(const Properties& props) {
  return std::make_shared<AreaEmitter>(props.getSpectrum("radiance", 1.0f, SpectrumUse::Emission));
}

}  // namespace columba
