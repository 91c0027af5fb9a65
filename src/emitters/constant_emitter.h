#pragma once
// `constant`: the same radiance from every direction at infinity.
#include "core/properties.h"
#include "emitters/emitter_at_infinity.h"

namespace columba {

class ConstantEmitter : public EmitterAtInfinity {
 public:
  explicit ConstantEmitter(SpectralDistribution radiance) : radiance_(std::move(radiance)) {}
  std::optional<EmitterSample> sample(const Vec3& ref, Vec2 u, const Wavelengths& wl) const override;
  Spectrum radianceFromDirection(const Vec3& d, const Wavelengths& wl) const override { return radiance_.sample(wl); }
  float pdfDirection(const Vec3& d) const override;

  bool isInfinite() const override { return true; }
  // Its samples are uniform over the sphere, half of them below the surface, and its radiance
  // is the same in every direction: a BSDF sample, which follows the surface's own lobes, finds
  // it as well or better (pbrt-v4 likewise leaves a uniform infinite light to BSDF sampling
  // where MIS compensates for it).
  bool leftToBSDFSamples() const override { return true; }

 private:
  SpectralDistribution radiance_;
};

std::shared_ptr<Object> makeConstantEmitter(const Properties& props);

}  // namespace columba
