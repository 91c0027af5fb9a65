#pragma once
// `directional`: light from infinitely far away along `direction`, of irradiance `irradiance`
// (W/m^2/nm) on a surface facing it.
#include "core/properties.h"
#include "emitters/emitter_at_infinity.h"

namespace columba {

class DirectionalEmitter : public EmitterAtInfinity {
 public:
  DirectionalEmitter(Vec3 direction, SpectralDistribution irradiance)
      : direction_(normalize(direction)), irradiance_(std::move(irradiance)) {}
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  bool isDelta() const override { return true; }

 private:
  Vec3 direction_;  // direction the light travels
  SpectralDistribution irradiance_;
};

std::shared_ptr<Object> makeDirectionalEmitter(const Properties& props);

}  // namespace columba
