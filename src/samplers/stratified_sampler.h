#pragma once
// Jittered stratified samples (pbrt-v4's StratifiedSampler): in every dimension a pixel's samples
// fall one per stratum (1D: sampleCount strata; 2D: a resolution x resolution grid), and each
// dimension assigns strata to sample indices by its own random permutation, so that
// dimensions are not correlated with each other.
#include <memory>
#include "samplers/pixel_sample_state.h"
#include "samplers/sampler.h"

namespace columba {

class Properties;

class StratifiedSampler : public Sampler {
 public:
  // sampleCount = resolution^2.
  StratifiedSampler(int resolution, bool jitter, uint64_t seed)
      : Sampler(resolution * resolution), resolution_(resolution), jitter_(jitter), seed_(seed) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<StratifiedSampler>(*this); }
  std::unique_ptr<Sampler> withSampleCount(int count) const override {
    return std::make_unique<StratifiedSampler>(resolutionFor(count), jitter_, seed_);
  }
  // The grid's side: the smallest square of at least `count` samples.
  static int resolutionFor(int count);
  void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) override;
  float get1D() override;
  Vec2 get2D() override;

 private:
  // Where in its stratum a sample lies: uniform if jittered, else the centre.
  float offset() { return jitter_ ? state_.rng.nextFloat() : 0.5f; }

  int resolution_;
  bool jitter_;
  uint64_t seed_;
  PixelSampleState state_;
};

// <sampler type="stratified">: its parameters are in docs/reference/samplers.md.
std::shared_ptr<Object> makeStratifiedSampler(const Properties& props);

}  // namespace columba
