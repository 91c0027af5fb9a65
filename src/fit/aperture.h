#pragma once
// What a microspectrophotometer or spectrometer collects: light from a cone of directions about
// the illumination axis, seen over a cone about the viewing axis (half-angle alpha, numerical
// aperture sin(alpha)). The model measured so is its average over both cones, each weighted
// uniformly in solid angle.
#include <vector>

#include "core/vector.h"

namespace columba {

struct InstrumentAperture {
  float halfAngleDeg = 0.0f;  // 0: a point measurement along the axes
  int rings = 4, azimuths = 12;

  bool isPoint() const { return !(halfAngleDeg > 0.0f); }
};

struct ConeDirection {
  Vec3 w;
  double weight;  // the weights of a cone sum to 1
};

// Directions over the cone of `aperture` about the unit `axis`: Gauss-Legendre in cos(theta)
// over [cos(alpha), 1] (uniform in solid angle) times `azimuths` evenly spaced azimuths.
std::vector<ConeDirection> coneDirections(const Vec3& axis, const InstrumentAperture& aperture);

}  // namespace columba
