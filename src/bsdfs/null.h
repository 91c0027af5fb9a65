#pragma once
// Mitsuba's `null`: the surface is not there for light. Rays and shadow rays pass straight
// through; it scatters nothing (a shape that only carries an emitter, or bounds a medium).
#include <memory>
#include "bsdfs/delta_bsdf.h"
#include "core/properties.h"

namespace columba {

class NullBSDF : public DeltaBSDF {
 public:
  std::optional<BSDFSample> sample(const BSDFContext&, const Vec3& wi, const Wavelengths&, float, Vec2) const override;
  Spectrum passThrough(const BSDFContext&, const Vec3&, const Wavelengths&) const override { return Spectrum(1.0f); }
  bool hasPassThrough() const override { return true; }
};

std::shared_ptr<Object> makeNullBSDF(const Properties& props);

}  // namespace columba
