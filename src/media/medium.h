#pragma once
// The medium interface: a participating medium's extinction and scattering coefficients at a point
// and the majorant, a bound on its extinction over a stretch of a ray, against which collisions
// are drawn (majorant_tracking.h). Coefficients are per unit of world distance.
#include <memory>
#include <optional>
#include "core/properties.h"
#include "core/ray.h"
#include "core/spectrum.h"
#include "media/phase_function.h"

namespace columba {

struct MediumCoefficients {
  Spectrum sigmaT;  // extinction
  Spectrum sigmaS;  // scattering: sigmaT times the albedo
};

// The part (tmin, tmax) of a ray where the medium may interact, with the majorant there.
struct MajorantSegment {
  float tmin = 0.0f, tmax = 0.0f;
  Spectrum sigmaMaj;
};

class Medium : public Object {
 public:
  explicit Medium(std::shared_ptr<PhaseFunction> phase) : phase_(std::move(phase)) {}
  const PhaseFunction& phase() const { return *phase_; }
  virtual MediumCoefficients coefficients(const Vec3& p, const Wavelengths& wl) const = 0;
  // Within ray.tmin to ray.tmax; nullopt where the ray does not meet the medium.
  virtual std::optional<MajorantSegment> majorant(const Ray& ray, const Wavelengths& wl) const = 0;

 private:
  std::shared_ptr<PhaseFunction> phase_;
};

// The nested phase function of a medium element, or the default (isotropic).
std::shared_ptr<PhaseFunction> mediumPhase(const Properties& props);
// A medium element's `scale` (1 by default), which must not be negative.
float mediumScale(const Properties& props);

}  // namespace columba
