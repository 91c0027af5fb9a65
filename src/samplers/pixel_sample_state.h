#pragma once
// What every sampler derives from startPixelSample: hashes of (pixel, seed, sample index) and a
// dimension counter. Nothing depends on call order across pixels or on threads.
#include <algorithm>
#include <cstdint>
#include "core/math.h"
#include "core/rng.h"

namespace columba {

inline float clampToUnitInterval(double v) { return std::min(float(v), kOneMinusEpsilon); }

struct PixelSampleState {
  uint32_t index = 0;  // sample index within its round
  uint32_t dimension = 0;
  PCG32 rng;  // independent randomness of this one pixel sample, after seedRandomness()

  // Samplers with a per-pixel pattern of `patternSize` samples use index 0..patternSize-1 of it;
  // sample indices past the pattern start a fresh pattern.
  void start(int px, int py, int sampleIndex, uint64_t seed, uint32_t patternSize) {
    // The renderer draws a pixel's samples one after another: the hashes of its pixel and pattern,
    // and of the pattern's first dimensions, are computed once.
    sample_ = uint32_t(sampleIndex);
    index = sample_ % patternSize;
    uint32_t round = sample_ / patternSize;
    if (!hasPixel_ || px != px_ || py != py_ || seed != seed_) {
      pixelHash_ = hashCombine(hashCombine(mixBits(seed), uint32_t(px)), uint32_t(py));
      px_ = px;
      py_ = py;
      seed_ = seed;
      hasPixel_ = true;
      startPattern(round);
    } else if (round != round_) {
      startPattern(round);
    }
    dimension = 0;
  }
  // Changes whenever the pattern does (a new pixel, seed or round): what a sampler derived from
  // the pattern's hashes is stale once this differs. Never 0.
  uint64_t patternGeneration() const { return generation_; }

  // Seeds `rng` for the current pixel sample (samplers that jitter or draw independent values).
  void seedRandomness() { rng.seedWith(hashCombine(pixelHash_, sample_), pixelHash_); }
  // A hash unique to the next dimension of this pixel's pattern.
  uint64_t nextDimensionHash() {
    uint32_t d = dimension++;
    if (d >= kCachedDimensions) return hashCombine(patternHash_, d);
    for (; cachedDimensions_ <= d; ++cachedDimensions_)
      dimensionHashes_[cachedDimensions_] = hashCombine(patternHash_, cachedDimensions_);
    return dimensionHashes_[d];
  }

 private:
  static constexpr uint32_t kCachedDimensions = 8;

  void startPattern(uint32_t round) {
    ++generation_;
    round_ = round;
    patternHash_ = hashCombine(pixelHash_, round);
    cachedDimensions_ = 0;
  }

  uint64_t pixelHash_ = 0, seed_ = 0;
  uint64_t patternHash_ = 0;  // (pixel, seed, round of patternSize samples)
  int px_ = 0, py_ = 0;
  bool hasPixel_ = false;
  uint32_t sample_ = 0, round_ = 0;
  uint64_t dimensionHashes_[kCachedDimensions] = {};
  uint32_t cachedDimensions_ = 0;  // entries of dimensionHashes_ computed for patternHash_
  uint64_t generation_ = 0;
};

}  // namespace columba
