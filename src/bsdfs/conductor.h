#pragma once
// Smooth metal (Mitsuba's `conductor`): a perfect mirror weighted by the metal's Fresnel
// reflectance at each wavelength. One-sided.
#include <memory>
#include <optional>
#include "bsdfs/bsdf_parameters.h"
#include "bsdfs/delta_bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class ConductorBSDF : public DeltaBSDF {
 public:
  // Without `ior` the mirror reflects everything (Fresnel = 1).
  ConductorBSDF(std::optional<ConductorIndexParameter> ior, SpectrumParameter specularReflectance)
      : ior_(std::move(ior)), specularReflectance_(std::move(specularReflectance)) {}
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

 private:
  std::optional<ConductorIndexParameter> ior_;
  SpectrumParameter specularReflectance_;
};

// <bsdf type="conductor">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeConductorBSDF(const Properties& props);

}  // namespace columba
