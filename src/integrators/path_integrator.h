#pragma once
// `path`: unidirectional path tracing with next-event estimation and multiple importance
// sampling of emitters and BSDFs (power heuristic), Russian roulette after `rr_depth`.
// Pass-through components (barbule gaps) continue the path without counting a bounce.
#include "integrators/integrator.h"
#include "core/properties.h"

namespace columba {

class PathIntegrator : public Integrator {
 public:
  PathIntegrator(int maxDepth, int rrDepth, bool hideEmitters)
      : maxDepth_(maxDepth), rrDepth_(rrDepth), hideEmitters_(hideEmitters) {}
  Spectrum radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                    uint64_t& rays) const override;

 private:
  int maxDepth_;  // longest path in vertices after the camera; -1: unlimited (Mitsuba's meaning)
  int rrDepth_;
  bool hideEmitters_;
};

std::shared_ptr<Object> makePathIntegrator(const Properties& props);

}  // namespace columba
