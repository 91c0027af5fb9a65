#pragma once
// Low-discrepancy samples (pbrt-v4's PaddedSobolSampler): every dimension pair of a pixel's
// samples is an Owen-scrambled (0, 2)-sequence in base 2 (the first two Sobol dimensions), so
// any power-of-two prefix of it is stratified over all elementary intervals. Each dimension
// scrambles with its own seed and shuffles which sample index gets which point, so
// dimensions are not correlated with each other.
#include <memory>
#include "render/sampler.h"
#include "render/samplers/pixel_sample_state.h"

namespace columba {

class Properties;

class LowDiscrepancySampler : public Sampler {
 public:
  // sampleCount must be a power of two.
  LowDiscrepancySampler(int sampleCount, uint64_t seed) : Sampler(sampleCount), seed_(seed) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<LowDiscrepancySampler>(*this); }
  void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) override;
  float get1D() override;
  Vec2 get2D() override;

 private:
  uint64_t seed_;
  PixelSampleState state_;
};

// <sampler type="ldsampler">: sample_count (4, rounded up to a power of two as Mitsuba does),
// seed (0).
std::shared_ptr<Object> makeLowDiscrepancySampler(const Properties& props);

}  // namespace columba
