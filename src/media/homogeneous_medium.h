#pragma once
// `homogeneous`: the same extinction and albedo everywhere (where shapes bound it). Its majorant
// is its extinction, so every collision drawn against it is real.
#include "core/properties.h"
#include "media/medium.h"

namespace columba {

class HomogeneousMedium final : public Medium {
 public:
  // sigmaT per unit distance (scale applied), albedo in [0, 1].
  HomogeneousMedium(SpectralDistribution sigmaT, SpectralDistribution albedo, float scale,
                    std::shared_ptr<PhaseFunction> phase, const Properties* element = nullptr)
      : Medium(std::move(phase), element), sigmaT_(std::move(sigmaT)), albedo_(std::move(albedo)), scale_(scale) {}
  MediumCoefficients coefficients(const Vec3& p, const Wavelengths& wl) const override;
  MajorantIterator majorant(const Ray& ray, const Wavelengths& wl) const override;

 private:
  SpectralDistribution sigmaT_, albedo_;
  float scale_;
};

std::shared_ptr<Object> makeHomogeneousMedium(const Properties& props);

}  // namespace columba
