#pragma once
// The barbule model of one set of parameters (docs/model.md): the cross-section they describe
// and the quadrature it is evaluated with, from which the model at any shading point is built.
// The BSDF plug-in (bsdfs/barbulebsdf.h) holds one; virtual measurements (barbule/measurement.h)
// evaluate it directly.
#include <optional>

#include "barbule/cross_section.h"
#include "barbule/lobe_source.h"
#include "barbule/parameters.h"
#include "barbule/point_model.h"

namespace columba {

class BarbuleModel final : public BarbuleLobeSource {
 public:
  explicit BarbuleModel(const BarbuleParameters& params, BarbuleQuadrature quadrature = {});

  const BarbuleParameters& parameters() const { return params_; }
  const BarbuleCrossSection& geometry() const { return geometry_; }

  // The model at a point with its own cross-section (`own`, the shared one when empty), film
  // thickness (micrometres, at least 0) and layer stack (0 to parameters().layerStackCount() - 1).
  BarbulePointModel at(std::optional<BarbuleCrossSection> own, float thicknessUm, const Wavelengths& wl,
                       int layerStack = 0) const;

  // The two non-delta lobes f(omega_i, omega_o) (without any cosine) with the parameters' own
  // cross-section and thickness.
  BarbuleLobes lobes(const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const override;
  // Coverage r(omega_i): the fraction of light from omega_i meeting the reflective arc (T = 1 - r).
  float coverage(const Vec3& omegaI) const override;

 private:
  BarbuleParameters params_;
  BarbuleCrossSection geometry_;
  BarbuleQuadratureRules rules_;
};

}  // namespace columba
