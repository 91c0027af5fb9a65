#pragma once
// The medium interface: a participating medium's extinction and scattering coefficients at a point
// and its majorants, bounds on its extinction along a ray, against which collisions are drawn
// (majorant_tracking.h). Coefficients are per unit of world distance.
#include <atomic>
#include <memory>
#include "core/error.h"
#include "core/properties.h"
#include "core/ray.h"
#include "core/spectrum.h"
#include "media/majorant_grid.h"
#include "media/phase_function.h"

namespace columba {

struct MediumCoefficients {
  Spectrum sigmaT;  // extinction
  Spectrum sigmaS;  // scattering: sigmaT times the albedo
};

class Medium : public Object {
 public:
  // `element`: the medium's element in the scene (its type, id and place name it in warnings).
  explicit Medium(std::shared_ptr<PhaseFunction> phase, const Properties* element = nullptr);
  const PhaseFunction& phase() const { return *phase_; }
  virtual MediumCoefficients coefficients(const Vec3& p, const Wavelengths& wl) const = 0;
  // The majorant segments within ray.tmin to ray.tmax; none where the ray does not meet the medium.
  virtual MajorantIterator majorant(const Ray& ray, const Wavelengths& wl) const = 0;
  // Warns, the first time only, that a walk through this medium was cut short after `collisions`
  // tentative collisions.
  void warnWalkCut(int collisions) const;

 private:
  std::shared_ptr<PhaseFunction> phase_;
  std::string name_;
  SourceLocation where_;
  mutable std::atomic<bool> warnedWalkCut_{false};
};

// The nested phase function of a medium element, or the default (isotropic).
std::shared_ptr<PhaseFunction> mediumPhase(const Properties& props);
// A medium element's `scale` (1 by default), which must not be negative.
float mediumScale(const Properties& props);

}  // namespace columba
