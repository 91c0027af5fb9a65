/*! plugin emitter projector
A projection light: the perspective camera run backwards. From the origin of `to_world`, looking along its +z, it projects `irradiance` through the same field of view and pixel-to-direction mapping as the `perspective` sensor; the image's aspect is the texture's (a bitmap's width over height; 1 for other textures). A point at (x, y, z) of its frame receives π · scale · irradiance / (z² cos θ), so a plane facing it at z = 1 is lit evenly.
Mitsuba 3: the same parameters; `to_world` must be rigid (the density of directions is the camera's).
uses: fov
| parameter | type | default | meaning | Mitsuba 3 |
| irradiance | spectrum or texture | required | the irradiance on the image plane z = 1; a single value or an RGB colour is CIE D65 of that luminance, a texture's spectra are taken as the texture gives them (no D65, as in Mitsuba 3) | same |
| scale | float | 1 | a factor on `irradiance` | same |
| to_world | transform | identity | the projector's frame; rotation and translation only | — |
*/
#include "emitters/projector_emitter.h"

#include "core/field_of_view.h"
#include "textures/bitmap_texture.h"

namespace columba {

ProjectorEmitter::ProjectorEmitter(const Transform& toWorld, SpectrumParameter irradiance, float scale, Vec2 tanHalf)
    : toWorld_(toWorld),
      worldToLocal_(toWorld.inverse()),
      position_(toWorld.point(Vec3(0, 0, 0))),
      axis_(toWorld.vector(Vec3(0, 0, 1))),
      irradiance_(std::move(irradiance)),
      scale_(scale),
      tanHalf_(tanHalf) {}

std::optional<Vec2> ProjectorEmitter::imageUVAt(const Vec3& local) const {
  if (!(local.z > 0.0f)) return std::nullopt;
  const Vec2 uv = imageUV(Vec2(local.x / local.z, local.y / local.z), tanHalf_);
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return std::nullopt;
  return uv;
}

std::optional<EmitterSample> ProjectorEmitter::sample(const Vec3& ref, Vec2, const Wavelengths& wl) const {
  const Vec3 local = worldToLocal_.point(ref);
  const std::optional<Vec2> uv = imageUVAt(local);
  if (!uv) return std::nullopt;
  EmitterSample s;
  const Vec3 d = position_ - ref;
  s.distance = length(d);
  if (!(s.distance > 0.0f)) return std::nullopt;
  s.direction = d / s.distance;
  const float cosTheta = -dot(axis_, s.direction);
  if (!(cosTheta > 0.0f)) return std::nullopt;
  s.radiance = irradiance_.eval(*uv, wl) * scale_ * (kPi / (local.z * local.z * cosTheta));
  s.pdf = 1.0f;
  return s;
}

std::optional<EmitterRaySample> ProjectorEmitter::sampleRay(Vec2, Vec2 uDirection, const Wavelengths& wl,
                                                            const SceneSphere&) const {
  // The point of the image plane z = 1 at uv = uDirection, whose density over that plane is one
  // over its area A; as solid angle that is 1 / (A cos^3 theta), against the intensity
  // pi * scale * irradiance / cos^3 theta that sample() implies.
  const Vec3 local((0.5f - uDirection.x) * 2.0f * tanHalf_.x, (0.5f - uDirection.y) * 2.0f * tanHalf_.y, 1.0f);
  EmitterRaySample s;
  s.ray.o = position_;
  s.ray.d = normalize(toWorld_.vector(local));
  s.weight = irradiance_.eval(uDirection, wl) * scale_ * (kPi * 4.0f * tanHalf_.x * tanHalf_.y);
  return s;
}

std::shared_ptr<Object> makeProjectorEmitter(const Properties& props) {
  if (!props.has("irradiance") && !props.namedChild<Texture>("irradiance"))
    throw InputError(props.location, "'projector' needs its 'irradiance' (a texture or a value)");
  SpectrumParameter irradiance = readSpectrumParameter(props, "irradiance", 1.0f, SpectrumUse::Emission);
  // The image's aspect is the texture's, as Mitsuba takes it from the texture's resolution; a
  // constant or procedural texture is square.
  float aspect = 1.0f;
  if (auto bitmap = std::dynamic_pointer_cast<const BitmapTexture>(props.namedChild<Texture>("irradiance")))
    aspect = float(bitmap->width()) / float(bitmap->height());
  const Transform toWorld = props.getTransform("to_world");
  if (!toWorld.isRigid())
    throw props.error("to_world", "a projector's to_world must not scale or shear (rotate and translate it only)");
  return std::make_shared<ProjectorEmitter>(toWorld, std::move(irradiance), props.getFloat("scale", 1.0f),
                                            tanHalfAngles(readFieldOfView(props), aspect));
}

}  // namespace columba
