#pragma once
// `point`: an isotropic point light of radiant intensity `intensity` (W/sr/nm).
#include "core/properties.h"
#include "emitters/emitter.h"

namespace columba {

class PointEmitter : public Emitter {
 public:
  PointEmitter(Vec3 position, SpectralDistribution intensity) : position_(position), intensity_(std::move(intensity)) {}
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  std::optional<EmitterRaySample> sampleRay(Vec2 uPosition, Vec2 uDirection, const Wavelengths& wl,
                                            const SceneSphere& scene) const override;
  bool isDelta() const override { return true; }

 private:
  Vec3 position_;
  SpectralDistribution intensity_;
};

std::shared_ptr<Object> makePointEmitter(const Properties& props);

}  // namespace columba
