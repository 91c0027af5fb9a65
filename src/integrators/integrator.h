#pragma once
// The integrator interface: radiance arriving along a camera ray at the path's wavelengths.
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
};

}  // namespace columba
