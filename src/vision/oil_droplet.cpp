#include "vision/oil_droplet.h"

#include <cmath>
#include <stdexcept>

namespace columba {

double oilDropletTransmission(const OilDroplet& droplet, double lambdaNm) {
  return std::exp(-std::exp(-2.89 * droplet.bMidPerNm * (lambdaNm - droplet.lambdaCutNm) + 1.08));
}

double oilDropletMidpoint(const OilDroplet& droplet) { return droplet.lambdaCutNm + 0.5 / droplet.bMidPerNm; }

OilDroplet oilDropletFromCutAndMid(double lambdaCutNm, double lambdaMidNm) {
  if (!(lambdaMidNm > lambdaCutNm))
    throw std::invalid_argument("an oil droplet's mid-point must lie above its cut-off");
  return {lambdaCutNm, 0.5 / (lambdaMidNm - lambdaCutNm)};
}

std::optional<OilDropletType> parseOilDropletType(const std::string& letter) {
  if (letter == "T") return OilDropletType::T;
  if (letter == "C") return OilDropletType::C;
  if (letter == "Y") return OilDropletType::Y;
  if (letter == "R") return OilDropletType::R;
  if (letter == "P") return OilDropletType::P;
  return std::nullopt;
}

std::optional<OilDroplet> oilDropletOfType(OilDropletType type, double lambdaCutNm) {
  // Slope and intercept of lambdaMid against lambdaCut, Hart & Vorobyev (2005), as in pavo's sensmodel.
  double slope = 1.0, intercept = 0.0;
  switch (type) {
    case OilDropletType::T:
      return std::nullopt;
    case OilDropletType::C:
      slope = 0.99, intercept = 24.38;
      break;
    case OilDropletType::Y:
      slope = 0.90, intercept = 70.03;
      break;
    case OilDropletType::R:
      slope = 0.99, intercept = 28.65;
      break;
    case OilDropletType::P:
      slope = 0.96, intercept = 33.57;
      break;
  }
  return oilDropletFromCutAndMid(lambdaCutNm, slope * lambdaCutNm + intercept);
}

}  // namespace columba
