#pragma once
// Correlated multi-jittered samples (Kensler 2013): in 2D a pixel's samples lie one per cell of
// a columns x rows grid and, at the same time, one per each of the sampleCount thin strata
// along either axis. Every dimension has its own pattern seed, so dimensions are not
// correlated with each other. 1D dimensions are jittered strata in a random order.
#include <memory>
#include "samplers/pixel_sample_state.h"
#include "samplers/sampler.h"

namespace columba {

class Properties;

class MultijitterSampler : public Sampler {
 public:
  // sampleCount = columns * rows.
  MultijitterSampler(int columns, int rows, bool jitter, uint64_t seed)
      : Sampler(columns * rows), columns_(columns), rows_(rows), jitter_(jitter), seed_(seed) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<MultijitterSampler>(*this); }
  std::unique_ptr<Sampler> withSampleCount(int count) const override;
  void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) override;
  float get1D() override;
  Vec2 get2D() override;

 private:
  float offset() { return jitter_ ? state_.rng.nextFloat() : 0.5f; }

  int columns_, rows_;
  bool jitter_;
  uint64_t seed_;
  PixelSampleState state_;
};

// <sampler type="multijitter">: its parameters are in docs/reference/samplers.md.
std::shared_ptr<Object> makeMultijitterSampler(const Properties& props);

}  // namespace columba
