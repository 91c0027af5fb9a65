#pragma once
// A BSDF whose scattering is all in delta components (mirrors, refraction, pass-through): it has
// no value or density toward a given direction, and emitter sampling is pointless at it.
#include "bsdfs/bsdf.h"

namespace columba {

class DeltaBSDF : public BSDF {
 public:
  Spectrum eval(const BSDFContext&, const Vec3&, const Vec3&, const Wavelengths&) const final { return Spectrum(0.0f); }
  float pdf(const BSDFContext&, const Vec3&, const Vec3&, const Wavelengths&) const final { return 0.0f; }
  bool isDeltaOnly() const final { return true; }
};

}  // namespace columba
