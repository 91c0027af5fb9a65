/*! plugin emitter spot
A spot light at the origin of `to_world`, shining along its +z: full intensity within `beam_width` of the axis, falling linearly in angle to zero at `cutoff_angle`. An optional nested `texture` is projected as Mitsuba projects it: the direction (x, y, z) of the light's frame looks it up at uv = (1/2 + x / (2 z tan(cutoff)), 1/2 + y / (2 z tan(cutoff))) and scales the intensity by its value there.
Mitsuba 3: the same parameters and defaults.
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | the light's position and direction | same |
| intensity | spectrum | 1 | the radiant intensity on the axis (W/sr/nm); a value or a colour is D65 of that luminance | same |
| cutoff_angle | float | 20 | the angle in degrees, in (0, 180], beyond which no light leaves | same |
| beam_width | float | 3/4 of `cutoff_angle` | the angle in degrees, 0 to `cutoff_angle`, within which the intensity is full | same |
| texture | texture | — | a nested texture projected by the light; a value is an error | same |
*/
#include "emitters/spot_emitter.h"

#include "core/sampling.h"

namespace columba {

SpotEmitter::SpotEmitter(const Transform& toWorld, SpectralDistribution intensity, float cutoff, float beamWidth,
                         std::shared_ptr<const Texture> texture)
    : worldToLocal_(toWorld.inverse()),
      localToWorld_(toWorld),
      worldToLocalVolume_(
          std::abs(dot(worldToLocal_.vector(Vec3(1, 0, 0)),
                       cross(worldToLocal_.vector(Vec3(0, 1, 0)), worldToLocal_.vector(Vec3(0, 0, 1)))))),
      position_(toWorld.point(Vec3(0, 0, 0))),
      intensity_(std::move(intensity)),
      cutoff_(cutoff),
      beamWidth_(beamWidth),
      cosCutoff_(std::cos(cutoff)),
      cosBeamWidth_(std::cos(beamWidth)),
      texture_(std::move(texture)) {}

Vec2 SpotEmitter::textureUV(const Vec3& local) const {
  const float scale = 0.5f / (local.z * std::tan(cutoff_));
  return Vec2(0.5f + local.x * scale, 0.5f + local.y * scale);
}

float SpotEmitter::falloff(const Vec3& local) const {
  float cosTheta = normalize(local).z;
  if (!(cosTheta > cosCutoff_)) return 0.0f;
  if (cosTheta >= cosBeamWidth_) return 1.0f;
  return (cutoff_ - safeAcos(cosTheta)) / (cutoff_ - beamWidth_);
}

std::optional<EmitterSample> SpotEmitter::sample(const Vec3& ref, Vec2, const Wavelengths& wl) const {
  Vec3 d = position_ - ref;
  float dist2 = lengthSquared(d);
  if (dist2 == 0.0f) return std::nullopt;
  const Vec3 local = worldToLocal_.vector(-d);
  float f = falloff(local);
  if (!(f > 0.0f)) return std::nullopt;
  EmitterSample s;
  s.distance = std::sqrt(dist2);
  s.direction = d / s.distance;
  s.radiance = intensity_.sample(wl) * (f / dist2);
  if (texture_) s.radiance *= texture_->evalSpectrum(textureUV(local), wl);
  s.pdf = 1.0f;
  return s;
}

// Uniform over the cone within the cutoff angle in the light's frame, the falloff and texture in
// the weight. A to_world that scales unevenly changes the density of the world direction w by
// |det M^-1| / |M^-1 w|^3 (M the linear part of to_world).
std::optional<EmitterRaySample> SpotEmitter::sampleRay(Vec2, Vec2 uDirection, const Wavelengths& wl,
                                                       const SceneSphere&) const {
  const Vec3 local = sampleUniformCone(uDirection, cosCutoff_);
  const float f = falloff(local);
  if (!(f > 0.0f)) return std::nullopt;
  EmitterRaySample s;
  s.ray.o = position_;
  s.ray.d = normalize(localToWorld_.vector(local));
  const float stretch = length(worldToLocal_.vector(s.ray.d));
  const float pdf = uniformConePdf(cosCutoff_) * worldToLocalVolume_ / (stretch * stretch * stretch);
  s.weight = intensity_.sample(wl) * (f / pdf);
  if (texture_) s.weight *= texture_->evalSpectrum(textureUV(local), wl);
  return s;
}

std::shared_ptr<Object> makeSpotEmitter(const Properties& props) {
  std::shared_ptr<const Texture> texture = props.namedChild<Texture>("texture");
  if (props.has("texture")) throw props.error("texture", "the projected 'texture' must be a <texture>");
  float cutoff = props.getFloat("cutoff_angle", 20.0f);
  if (!(cutoff > 0.0f && cutoff <= 180.0f))
    throw props.error("cutoff_angle", "must lie in (0, 180] degrees, not " + std::to_string(cutoff));
  float beamWidth = props.getFloat("beam_width", 0.75f * cutoff);
  if (!(beamWidth >= 0.0f && beamWidth <= cutoff))
    throw props.error("beam_width", "must lie between 0 and cutoff_angle (" + std::to_string(cutoff) +
                                        " degrees), not " + std::to_string(beamWidth));
  return std::make_shared<SpotEmitter>(props.getTransform("to_world"),
                                       props.getSpectrum("intensity", 1.0f, SpectrumUse::Emission), degToRad(cutoff),
                                       degToRad(beamWidth), texture);
}

}  // namespace columba
