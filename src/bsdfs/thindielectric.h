#pragma once
// Mitsuba's `thindielectric`: a thin sheet of dielectric (a window pane). Light is mirrored with
// the sheet's reflectance or passes straight through (no refraction: the two faces are parallel),
// on either side. With the unpolarised Fresnel reflectance r at the incidence angle, the light
// bouncing between the faces sums to R = r + t^2 r / (1 - r^2) = 2 r / (1 + r) and T = 1 - R.
// The transmission is a pass-through, so shadow rays cross the sheet with weight T.
#include <memory>
#include "bsdfs/delta_bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class ThinDielectricBSDF : public DeltaBSDF {
 public:
  // eta = interior / exterior index.
  ThinDielectricBSDF(float eta, SpectrumParameter specularReflectance, SpectrumParameter specularTransmittance)
      : eta_(eta),
        specularReflectance_(std::move(specularReflectance)),
        specularTransmittance_(std::move(specularTransmittance)) {}
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  Spectrum passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const override;
  bool hasPassThrough() const override { return true; }
  // R for light meeting the sheet at incidence cosine `cosI` (either side).
  float sheetReflectance(float cosI) const;

 private:
  float eta_;
  SpectrumParameter specularReflectance_, specularTransmittance_;
};

// <bsdf type="thindielectric">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeThinDielectricBSDF(const Properties& props);

}  // namespace columba
