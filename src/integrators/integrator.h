#pragma once
// The integrator interface: radiance arriving along a camera ray at the path's wavelengths.
#include <string>

#include "core/properties.h"
#include "core/ray.h"
#include "core/spectrum.h"
#include "samplers/sampler.h"

namespace columba {

class Scene;

class Integrator : public Object {
 public:
  // `rays` counts the rays traced (for statistics).
  virtual Spectrum radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                            uint64_t& rays) const = 0;
  // Whether it follows light through participating media; the others render surfaces only.
  virtual bool tracesMedia() const { return false; }
  // What it is, where it weighs BSDF values at directions it did not sample from the BSDF, alone
  // (emitter sampling without MIS): "" where it does not.
  virtual std::string weighsBSDFValuesAlone() const { return ""; }
};

// Reads the pass parameters Mitsuba's sampling integrators take. `samples_per_pass` only splits
// Mitsuba's render into passes of the same samples, so the image is the same and Columba renders
// them in one. A positive `timeout` stops Mitsuba's render early; Columba renders every sample and
// warns, naming the line.
void readMitsubaPassParameters(const Properties& props);

}  // namespace columba
