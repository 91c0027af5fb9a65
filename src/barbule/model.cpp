#include "barbule/model.h"

#include <algorithm>

namespace columba {

BarbuleModel::BarbuleModel(const BarbuleParameters& params, BarbuleQuadrature quadrature)
    : params_(params),
      geometry_(params.b, params.phi0, params.phi1, params.mu, params.H, params.profileExponent),
      rules_(quadrature) {}

BarbulePointModel BarbuleModel::at(std::optional<BarbuleCrossSection> own, float thicknessUm, const Wavelengths& wl,
                                   int layerStack) const {
  return BarbulePointModel(std::move(own), geometry_, params_, thicknessUm, wl, rules_, layerStack);
}

BarbuleLobes BarbuleModel::lobes(const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const {
  BarbulePointModel point = at(std::nullopt, std::max(params_.height, 0.0f), wl);
  BarbuleIncident in = point.incident(omegaI);
  return point.lobes(in, point.outgoing(in, omegaO, point.litArc(omegaO)));
}

float BarbuleModel::coverage(const Vec3& omegaI) const { return 1.0f - gapTransmission(geometry_, omegaI); }

}  // namespace columba
