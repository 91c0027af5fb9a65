#pragma once
// Uniform random samples, independent across dimensions, samples and pixels.
#include <memory>
#include "samplers/pixel_sample_state.h"
#include "samplers/sampler.h"

namespace columba {

class Properties;

class IndependentSampler : public Sampler {
 public:
  IndependentSampler(int sampleCount, uint64_t seed) : Sampler(sampleCount), seed_(seed) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }
  std::unique_ptr<Sampler> withSampleCount(int count) const override {
    return std::make_unique<IndependentSampler>(count, seed_);
  }
  void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) override;
  float get1D() override;
  Vec2 get2D() override;

 private:
  uint64_t seed_;
  PixelSampleState state_;
};

// <sampler type="independent">: its parameters are in docs/reference/samplers.md.
std::shared_ptr<Object> makeIndependentSampler(const Properties& props);

}  // namespace columba
