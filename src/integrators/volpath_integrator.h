#pragma once
// `volpath` and `volpathmis`, Mitsuba's volumetric path tracers: unidirectional path tracing
// through participating media (delta tracking against each medium's majorant, with null
// collisions) and surfaces, next-event estimation at every vertex with transmittance by ratio
// tracking, and multiple importance sampling over emitter and BSDF or phase samples and over the
// path's wavelengths (integrators/volume_transport.h). A scene without media is rendered by the
// path integrator with the same parameters, bit for bit, and without any medium bookkeeping.
#include "core/properties.h"
#include "core/rng.h"
#include "integrators/path_integrator.h"
#include "integrators/volume_transport.h"

namespace columba {

class VolumetricPathIntegrator : public Integrator {
 public:
  explicit VolumetricPathIntegrator(std::shared_ptr<const PathIntegrator> surfacesOnly)
      : surfacesOnly_(std::move(surfacesOnly)) {}
  Spectrum radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                    uint64_t& rays) const override;
  bool tracesMedia() const override { return true; }

 private:
  Spectrum radianceInMedia(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                           uint64_t& rays) const;
  std::shared_ptr<const PathIntegrator> surfacesOnly_;  // for scenes without media; holds the parameters
};

std::shared_ptr<Object> makeVolumetricPathIntegrator(const Properties& props);

}  // namespace columba
