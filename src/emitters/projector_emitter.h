#pragma once
// `projector`: Mitsuba's projection light, a perspective camera run backwards. From the origin of
// `to_world`, looking along its +z, it projects `irradiance` (a texture, or a constant) through
// the same field of view and pixel-to-direction mapping as the `perspective` sensor (fov,
// fov_axis or focal_length; the image's aspect is the texture's). The texture gives the irradiance
// on the image plane z = 1 (a constant value or colour is CIE D65 of that luminance; a texture's
// spectra are taken as given, as Mitsuba 3 does), times the number `scale`: a point at local (x, y, z) receives, along the direction from the projector,
//   pi * scale * irradiance(uv) / (z^2 cos theta),
// theta the angle from the axis, so that a plane facing the projector at z = 1 is lit evenly, as
// Mitsuba writes it. Its uv is (1/2 - x / (2 z tan_x), 1/2 - y / (2 z tan_y)), with tan_x and
// tan_y the half extents of the image plane; nothing is sent outside [0, 1]^2.
#include <memory>
#include "core/properties.h"
#include "core/transform.h"
#include "emitters/emitter.h"
#include "textures/textured_parameter.h"

namespace columba {

class ProjectorEmitter : public Emitter {
 public:
  ProjectorEmitter(const Transform& toWorld, SpectrumParameter irradiance, float scale, Vec2 tanHalf);
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  // A ray through a point of the image chosen uniformly (Mitsuba chooses it by the texture's
  // values): its weight is pi * scale * irradiance * the image's area at z = 1.
  std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                            const SceneSphere& scene) const override;
  bool isDelta() const override { return true; }
  // Where the image is looked up for the local point `local`; nullopt outside the image or behind.
  std::optional<Vec2> imageUVAt(const Vec3& local) const;

 private:
  Transform toWorld_, worldToLocal_;
  Vec3 position_, axis_;
  SpectrumParameter irradiance_;
  float scale_ = 1.0f;
  Vec2 tanHalf_;
};

// <emitter type="projector">: its parameters are in docs/reference/emitters.md.
std::shared_ptr<Object> makeProjectorEmitter(const Properties& props);

}  // namespace columba
