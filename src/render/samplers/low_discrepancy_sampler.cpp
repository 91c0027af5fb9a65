#include "render/samplers/low_discrepancy_sampler.h"

#include "render/samplers/hashed_permutation.h"
#include "render/samplers/sampler_parameters.h"
#include "render/samplers/sobol.h"

namespace columba {

void LowDiscrepancySampler::startPixelSample(int px, int py, int sampleIndex, uint64_t seed) {
  state_.start(px, py, sampleIndex, hashCombine(seed, seed_), uint32_t(sampleCount_));
}

float LowDiscrepancySampler::get1D() {
  uint64_t hash = state_.nextDimensionHash();
  uint32_t index = permutationElementPowerOfTwo(state_.index, uint32_t(sampleCount_) - 1, uint32_t(hash));
  // Dimension 0 of the sequence, bit-reversed, is the index itself.
  return fractionToFloat(owenScrambleReversed(index, uint32_t(hash >> 32)));
}

Vec2 LowDiscrepancySampler::get2D() {
  uint64_t hash = state_.nextDimensionHash();
  uint32_t index = permutationElementPowerOfTwo(state_.index, uint32_t(sampleCount_) - 1, uint32_t(hash));
  uint64_t scrambleSeeds = mixBits(hash);
  return {fractionToFloat(owenScrambleReversed(index, uint32_t(scrambleSeeds))),
          fractionToFloat(owenScrambleReversed(sobolDimension1Reversed(index), uint32_t(scrambleSeeds >> 32)))};
}

std::shared_ptr<Object> makeLowDiscrepancySampler(const Properties& props) {
  SamplerParameters p = readSamplerParameters(props);
  int sampleCount = 1;
  while (sampleCount < p.sampleCount) sampleCount *= 2;
  return std::make_shared<LowDiscrepancySampler>(sampleCount, p.seed);
}

}  // namespace columba
