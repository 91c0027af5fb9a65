#pragma once
// `area`: radiance leaving the front side of a shape: the same everywhere, or a texture looked up
// at each point of the shape (its uv, or a mesh's attributes there), as in Mitsuba.
#include "core/properties.h"
#include "emitters/emitter.h"
#include "textures/textured_parameter.h"

namespace columba {

class AreaEmitter : public Emitter {
 public:
  explicit AreaEmitter(SpectrumParameter radiance) : radiance_(std::move(radiance)) {}
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  float pdfHit(const Vec3& ref, const SurfaceInteraction& hit) const override;
  Spectrum radianceAt(const SurfaceInteraction& hit, const Vec3& toViewer, const Wavelengths& wl) const override;
  std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                            const SceneSphere& scene) const override;
  std::optional<PositionSample> samplePosition(Vec2 u) const override;
  void attachTo(const Shape* shape) override;

 private:
  SpectrumParameter radiance_;
  const Shape* shape_ = nullptr;
};

std::shared_ptr<Object> makeAreaEmitter(const Properties& props);

}  // namespace columba
