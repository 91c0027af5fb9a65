#pragma once
// Smooth interface between two dielectrics (Mitsuba's `dielectric`): delta reflection and
// refraction, one of them chosen with the Fresnel reflectance as its probability.
#include <memory>
#include "bsdfs/delta_bsdf.h"
#include "core/properties.h"
#include "textures/textured_parameter.h"

namespace columba {

class DielectricBSDF : public DeltaBSDF {
 public:
  // eta = interior / exterior index; the normal (local +z) points to the exterior.
  DielectricBSDF(float eta, SpectrumParameter specularReflectance, SpectrumParameter specularTransmittance)
      : eta_(eta),
        specularReflectance_(std::move(specularReflectance)),
        specularTransmittance_(std::move(specularTransmittance)) {}
  // Refraction scales the weight by (n_wi / n_wo)^2: radiance is compressed into the smaller
  // solid angle on the denser side. Paths start at the camera, so this is the radiance form.
  std::optional<BSDFSample> sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl, float uComponent,
                                   Vec2 u) const override;
  float eta() const { return eta_; }

 private:
  float eta_;
  SpectrumParameter specularReflectance_, specularTransmittance_;
};

// <bsdf type="dielectric">: its parameters are in docs/reference/bsdfs.md.
std::shared_ptr<Object> makeDielectricBSDF(const Properties& props);

}  // namespace columba
