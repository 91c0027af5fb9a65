#pragma once
// Mitsuba's `null`: the surface is not there for light. Rays and shadow rays pass straight
// through; it scatters nothing (a shape that only carries an emitter, or bounds a medium).
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"

namespace columba {

class NullBSDF : public BSDF {
 public:
  Spectrum eval(const BSDFContext&, const Vec3&, const Vec3&, const Wavelengths&) const override {
    return Spectrum(0.0f);
  }
  float pdf(const BSDFContext&, const Vec3&, const Vec3&, const Wavelengths&) const override { return 0.0f; }
  std::optional<BSDFSample> sample(const BSDFContext&, const Vec3& wi, const Wavelengths&, float, Vec2) const override;
  Spectrum passThrough(const BSDFContext&, const Vec3&, const Wavelengths&) const override { return Spectrum(1.0f); }
  bool hasPassThrough() const override { return true; }
  bool isDeltaOnly() const override { return true; }
};

std::shared_ptr<Object> makeNullBSDF(const Properties& props);

}  // namespace columba
