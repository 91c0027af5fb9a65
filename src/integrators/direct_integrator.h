#pragma once
// `direct`: direct illumination only, from `emitter_samples` emitter samples and `bsdf_samples`
// BSDF samples per hit, combined by MIS when both are used. Camera rays continue through
// pass-through surfaces with their transmitted weight.
#include "core/properties.h"
#include "integrators/integrator.h"

namespace columba {

class DirectIntegrator : public Integrator {
 public:
  DirectIntegrator(int emitterSamples, int bsdfSamples, bool hideEmitters)
      : emitterSamples_(emitterSamples), bsdfSamples_(bsdfSamples), hideEmitters_(hideEmitters) {}
  Spectrum radiance(const Scene& scene, const Ray& ray, Sampler& sampler, const Wavelengths& wl,
                    uint64_t& rays) const override;
  std::string weighsBSDFValuesAlone() const override {
    return bsdfSamples_ == 0 && emitterSamples_ > 0 ? "direct with bsdf_samples 0" : "";
  }

 private:
  int emitterSamples_, bsdfSamples_;
  bool hideEmitters_;
};

std::shared_ptr<Object> makeDirectIntegrator(const Properties& props);

}  // namespace columba
