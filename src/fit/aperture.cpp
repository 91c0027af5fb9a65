#include "fit/aperture.h"

#include <cmath>

#include "core/frame.h"
#include "core/gauss_legendre.h"
#include "core/math.h"

namespace columba {

std::vector<ConeDirection> coneDirections(const Vec3& axis, const InstrumentAperture& aperture) {
  if (aperture.isPoint()) return {{axis, 1.0}};
  const double cosAlpha = std::cos(double(degToRad(aperture.halfAngleDeg)));
  const GaussLegendreRule rule = gaussLegendre(aperture.rings);
  const Frame frame = Frame::fromNormal(axis);
  std::vector<ConeDirection> directions;
  for (size_t r = 0; r < rule.nodes.size(); ++r) {
    const double cosTheta = cosAlpha + (1.0 - cosAlpha) * rule.nodes[r];
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    for (int a = 0; a < aperture.azimuths; ++a) {
      const double phi = 2.0 * kPi * (double(a) + 0.5) / double(aperture.azimuths);
      const Vec3 local(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
      directions.push_back({frame.toWorld(local), rule.weights[r] / double(aperture.azimuths)});
    }
  }
  return directions;
}

}  // namespace columba
