#pragma once
// What every sampler derives from startPixelSample: hashes of (pixel, seed, sample index) and a
// dimension counter. Nothing depends on call order across pixels or on threads.
#include <algorithm>
#include <cstdint>
#include "core/rng.h"

namespace columba {

// The largest float below 1: samples must stay in [0, 1).
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

inline float clampToUnitInterval(double v) { return std::min(float(v), kOneMinusEpsilon); }

struct PixelSampleState {
  uint64_t patternHash = 0;  // (pixel, seed, round of sampleCount samples)
  uint32_t index = 0;        // sample index within its round
  uint32_t dimension = 0;
  PCG32 rng;                 // independent randomness of this one pixel sample, after seedRandomness()

  // Samplers with a per-pixel pattern of `patternSize` samples use index 0..patternSize-1 of it;
  // sample indices past the pattern start a fresh pattern.
  void start(int px, int py, int sampleIndex, uint64_t seed, uint32_t patternSize) {
    // The renderer draws a pixel's samples one after another: its hash is computed once.
    if (!hasPixel_ || px != px_ || py != py_ || seed != seed_) {
      pixelHash_ = hashCombine(hashCombine(mixBits(seed), uint32_t(px)), uint32_t(py));
      px_ = px;
      py_ = py;
      seed_ = seed;
      hasPixel_ = true;
    }
    sample_ = uint32_t(sampleIndex);
    index = sample_ % patternSize;
    patternHash = hashCombine(pixelHash_, sample_ / patternSize);
    dimension = 0;
  }
  // Seeds `rng` for the current pixel sample (samplers that jitter or draw independent values).
  void seedRandomness() { rng.seedWith(hashCombine(pixelHash_, sample_), pixelHash_); }
  // A hash unique to the next dimension of this pixel's pattern.
  uint64_t nextDimensionHash() { return hashCombine(patternHash, dimension++); }

 private:
  uint64_t pixelHash_ = 0, seed_ = 0;
  int px_ = 0, py_ = 0;
  bool hasPixel_ = false;
  uint32_t sample_ = 0;
};

}  // namespace columba
