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
  PCG32 rng;                 // independent randomness of this one pixel sample

  // Samplers with a per-pixel pattern of `patternSize` samples use index 0..patternSize-1 of it;
  // sample indices past the pattern start a fresh pattern.
  void start(int px, int py, int sampleIndex, uint64_t seed, uint32_t patternSize) {
    uint64_t pixelHash = hashCombine(hashCombine(mixBits(seed), uint32_t(px)), uint32_t(py));
    uint32_t sample = uint32_t(sampleIndex);
    index = sample % patternSize;
    patternHash = hashCombine(pixelHash, sample / patternSize);
    dimension = 0;
    rng.seedWith(hashCombine(pixelHash, sample), pixelHash);
  }
  // A hash unique to the next dimension of this pixel's pattern.
  uint64_t nextDimensionHash() { return hashCombine(patternHash, dimension++); }
};

}  // namespace columba
