#pragma once
// What the virtual measurements (barbule/measurement.h) evaluate: a barbule model's two non-delta
// lobes and its coverage, whatever its cross-section (the ellipse model, BarbuleModel, or the
// chain of arms of `barbulearms`).
#include "barbule/point_model.h"

namespace columba {

class BarbuleLobeSource {
 public:
  // f_R and f_TRT (omega_i, omega_o), without any cosine; a model without TRT gives it as 0.
  virtual BarbuleLobes lobes(const Vec3& omegaI, const Vec3& omegaO, const Wavelengths& wl) const = 0;
  // The fraction of light from omega_i meeting the film-coated surface (T = 1 - coverage).
  virtual float coverage(const Vec3& omegaI) const = 0;

 protected:
  ~BarbuleLobeSource() = default;
};

}  // namespace columba
