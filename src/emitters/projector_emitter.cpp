#include "emitters/projector_emitter.h"

#include "core/field_of_view.h"
#include "textures/bitmap_texture.h"

namespace columba {

ProjectorEmitter::ProjectorEmitter(const Transform& toWorld, SpectrumParameter irradiance, SpectralDistribution scale,
                                   Vec2 tanHalf)
    : toWorld_(toWorld),
      worldToLocal_(toWorld.inverse()),
      position_(toWorld.point(Vec3(0, 0, 0))),
      axis_(toWorld.vector(Vec3(0, 0, 1))),
      irradiance_(std::move(irradiance)),
      scale_(std::move(scale)),
      tanHalf_(tanHalf) {}

std::optional<Vec2> ProjectorEmitter::imageUV(const Vec3& local) const {
  if (!(local.z > 0.0f)) return std::nullopt;
  const Vec2 uv(0.5f - local.x / (2.0f * local.z * tanHalf_.x), 0.5f - local.y / (2.0f * local.z * tanHalf_.y));
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return std::nullopt;
  return uv;
}

std::optional<EmitterSample> ProjectorEmitter::sample(const Vec3& ref, Vec2, const Wavelengths& wl) const {
  const Vec3 local = worldToLocal_.point(ref);
  const std::optional<Vec2> uv = imageUV(local);
  if (!uv) return std::nullopt;
  EmitterSample s;
  const Vec3 d = position_ - ref;
  s.distance = length(d);
  if (!(s.distance > 0.0f)) return std::nullopt;
  s.direction = d / s.distance;
  const float cosTheta = -dot(axis_, s.direction);
  if (!(cosTheta > 0.0f)) return std::nullopt;
  s.radiance = irradiance_.eval(*uv, wl) * scale_.sample(wl) * (kPi / (local.z * local.z * cosTheta));
  s.pdf = 1.0f;
  return s;
}

std::shared_ptr<Object> makeProjectorEmitter(const Properties& props) {
  if (!props.has("irradiance") && !props.namedChild<Texture>("irradiance"))
    throw InputError(props.location, "'projector' needs its 'irradiance' (a texture or a value)");
  SpectrumParameter irradiance = readSpectrumParameter(props, "irradiance", 1.0f, SpectrumUse::Unbounded);
  // The image's aspect is the texture's, as Mitsuba takes it from the texture's resolution; a
  // constant or procedural texture is square.
  float aspect = 1.0f;
  if (auto bitmap = std::dynamic_pointer_cast<const BitmapTexture>(props.namedChild<Texture>("irradiance")))
    aspect = float(bitmap->width()) / float(bitmap->height());
  return std::make_shared<ProjectorEmitter>(props.getTransform("to_world"), std::move(irradiance),
                                            props.getSpectrum("scale", 1.0f, SpectrumUse::Emission),
                                            tanHalfAngles(readFieldOfView(props), aspect));
}

}  // namespace columba
