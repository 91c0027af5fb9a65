#pragma once
// Lambertian reflection (Mitsuba's `diffuse`). One-sided: black when seen from below.
#include <memory>
#include "bsdfs/bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class DiffuseBSDF : public BSDF {
 public:
  explicit DiffuseBSDF(SpectrumParameter reflectance) : reflectance_(std::move(reflectance)) {}
  Spectrum eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  float pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const override;
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;

 private:
  SpectrumParameter reflectance_;
};

// <bsdf type="diffuse">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeDiffuseBSDF(const Properties& props);

}  // namespace columba
