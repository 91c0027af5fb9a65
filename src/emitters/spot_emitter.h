#pragma once
// `spot`: Mitsuba's spot light. At the origin of `to_world`, shining along its +z, with radiant
// intensity `intensity` (W/sr/nm) on the axis: full within `beam_width` degrees of it, falling
// linearly in angle to zero at `cutoff_angle` (20 degrees; beam_width 3/4 of it by default).
// An optional `texture` is projected as Mitsuba projects it: the direction (x, y, z) in the light's
// frame looks the texture up at uv = (1/2 + x / (2 z tan(cutoff)), 1/2 + y / (2 z tan(cutoff))),
// and scales the intensity by its value there.
#include <memory>
#include "core/properties.h"
#include "core/transform.h"
#include "emitters/emitter.h"
#include "textures/texture.h"

namespace columba {

class SpotEmitter : public Emitter {
 public:
  // Angles in radians, 0 <= beamWidth <= cutoff.
  SpotEmitter(const Transform& toWorld, SpectralDistribution intensity, float cutoff, float beamWidth,
              std::shared_ptr<const Texture> texture = nullptr);
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                            const SceneSphere& scene) const override;
  bool isDelta() const override { return true; }
  // The fraction of the axis' intensity sent along the light's local direction `local` (any length).
  float falloff(const Vec3& local) const;
  // Where the projected texture is looked up for the local direction `local` (z > 0).
  Vec2 textureUV(const Vec3& local) const;

 private:
  Transform worldToLocal_, localToWorld_;
  float worldToLocalVolume_;  // |det| of worldToLocal_: how it scales directions' density
  Vec3 position_;
  SpectralDistribution intensity_;
  float cutoff_, beamWidth_, cosCutoff_, cosBeamWidth_;
  std::shared_ptr<const Texture> texture_;  // or null
};

std::shared_ptr<Object> makeSpotEmitter(const Properties& props);

}  // namespace columba
