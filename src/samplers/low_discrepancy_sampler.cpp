/*! plugin sampler ldsampler
Owen-scrambled Sobol points: a sample's first four 2D points come from one eight-dimensional sequence, so that the wavelengths, the position in the pixel and the first vertex's choices are stratified together (on the paper's simulation1 and simulation3, 38–40 % less variance per sample at 256 spp than with every point padded); later points are padded as in pbrt-v4's padded Sobol sampler. `sample_count` is rounded up to a power of two.
Mitsuba 3: the same parameters and defaults; unlike Mitsuba 3's, two 1D requests of a sample are the two coordinates of one 2D point, so the wavelengths and the first vertex's lobe choice are paired.
uses: sampler
*/
#include "samplers/low_discrepancy_sampler.h"

#include "samplers/hashed_permutation.h"
#include "samplers/sampler_parameters.h"
#include "samplers/sobol.h"

namespace columba {

namespace {

// Which of the pattern's points sample `index` gets in a dimension: a random permutation, or for
// the progressive pattern the nested scrambling of sobol.h applied to the index read top bit first
// (each bit flipped as a function of the bits above it).
inline uint32_t permuted(uint32_t index, uint32_t sampleCount, uint64_t dimensionHash) {
  return permutationElementPowerOfTwo(index, sampleCount - 1, uint32_t(dimensionHash));
}
// The index given as index << shift, shift = 32 - log2(sampleCount) (sampleCount > 1): its top bit
// first.
inline uint32_t scrambledFromTheTop(uint32_t shiftedIndex, int shift, uint64_t dimensionHash) {
  return owenScrambleReversed(reverseBits(shiftedIndex), uint32_t(dimensionHash)) >> shift;
}
inline int scrambleShift(uint32_t sampleCount) { return __builtin_clz(sampleCount - 1); }
inline uint32_t shuffled(uint32_t index, uint32_t sampleCount, uint64_t dimensionHash, bool progressive) {
  if (!progressive) return permuted(index, sampleCount, dimensionHash);
  if (sampleCount == 1) return 0;
  const int shift = scrambleShift(sampleCount);
  return scrambledFromTheTop(index << shift, shift, dimensionHash);
}

// Scramble seeds of a 2D dimension's two coordinates.
inline uint64_t scrambleSeeds2D(uint64_t dimensionHash) { return mixBits(dimensionHash); }

// Dimension 0 of the sequence, bit-reversed, is the point's index itself.
inline float coordinate0(uint32_t point, uint32_t seed) { return fractionToFloat(owenScrambleReversed(point, seed)); }
inline float coordinate1(uint32_t point, uint32_t seed) {
  return fractionToFloat(owenScrambleReversed(sobolDimension1Reversed(point), seed));
}

// The tables, a pass per step so that each loop vectorises; built for AVX2 too, chosen at run time.
__attribute__((target_clones("avx2", "default"))) void fillShuffled(uint32_t sampleCount, uint64_t dimensionHash,
                                                                    bool progressive, uint32_t* points) {
  // A loop per kind, without branches, so that each vectorises.
  if (!progressive) {
    for (uint32_t i = 0; i < sampleCount; ++i) points[i] = permuted(i, sampleCount, dimensionHash);
  } else if (sampleCount == 1) {
    points[0] = 0;
  } else {
    // Two passes: GCC does not vectorise the bit reversal of the loop counter itself.
    const int shift = scrambleShift(sampleCount);
    for (uint32_t i = 0; i < sampleCount; ++i) points[i] = i << shift;
    for (uint32_t i = 0; i < sampleCount; ++i) points[i] = scrambledFromTheTop(points[i], shift, dimensionHash);
  }
}

__attribute__((target_clones("avx2", "default"))) void fillScrambled(uint32_t count, const uint32_t* reversed,
                                                                     uint32_t seed, float* out) {
  for (uint32_t i = 0; i < count; ++i) out[i] = fractionToFloat(owenScrambleReversed(reversed[i], seed));
}

// sobolReversed(dimension, .) of points below `count`, a power of two, as the xor of the generator
// columns of their set bits, a bit at a time across all points.
__attribute__((target_clones("avx2", "default"))) void fillSobolReversed(uint32_t count, int dimension,
                                                                         const uint32_t* points, uint32_t* out) {
  const uint32_t* columns = sobolReversedColumns(dimension);
  for (uint32_t i = 0; i < count; ++i) out[i] = 0;
  for (uint32_t k = 0; (1u << k) < count; ++k)
    for (uint32_t i = 0; i < count; ++i) out[i] ^= (0u - ((points[i] >> k) & 1u)) & columns[k];
}

}  // namespace

Vec2 LowDiscrepancySampler::point2D(uint32_t point, uint32_t index, uint32_t sampleCount, uint64_t dimensionHash,
                                    bool progressive) {
  uint64_t seeds = scrambleSeeds2D(dimensionHash);
  if (point < kSobolPoints) {
    const auto [dx, dy] = kSobolPointDimensions[point];
    return {fractionToFloat(owenScrambleReversed(sobolReversed(dx, index), uint32_t(seeds))),
            fractionToFloat(owenScrambleReversed(sobolReversed(dy, index), uint32_t(seeds >> 32)))};
  }
  uint32_t shuffledIndex = shuffled(index, sampleCount, dimensionHash, progressive);
  return {coordinate0(shuffledIndex, uint32_t(seeds)), coordinate1(shuffledIndex, uint32_t(seeds >> 32))};
}

void LowDiscrepancySampler::startPixelSample(int px, int py, int sampleIndex, uint64_t seed) {
  state_.start(px, py, sampleIndex, hashCombine(seed, seed_), uint32_t(sampleCount_));
  hasPendingY_ = false;
}

void LowDiscrepancySampler::fill(DimensionTable& t, uint32_t point, uint64_t dimensionHash) {
  const uint32_t n = uint32_t(sampleCount_);
  t.generation = state_.patternGeneration();
  t.values.resize(2 * size_t(n));
  scratch_.resize(2 * size_t(n));
  uint32_t* indices = scratch_.data();
  uint32_t* sobol = scratch_.data() + n;
  const uint64_t seeds = scrambleSeeds2D(dimensionHash);
  if (point < kSobolPoints) {
    // Sample index i takes point i of the sequence in both of the point's dimensions.
    const auto [dx, dy] = kSobolPointDimensions[point];
    fillScrambled(n, sequence(dx), uint32_t(seeds), t.values.data());
    fillScrambled(n, sequence(dy), uint32_t(seeds >> 32), t.values.data() + n);
    return;
  }
  fillShuffled(n, dimensionHash, progressive_, indices);
  fillScrambled(n, indices, uint32_t(seeds), t.values.data());  // dimension 0: the point itself
  fillSobolReversed(n, 1, indices, sobol);
  fillScrambled(n, sobol, uint32_t(seeds >> 32), t.values.data() + n);
}

const uint32_t* LowDiscrepancySampler::sequence(int dimension) {
  std::vector<uint32_t>& points = sequences_[size_t(dimension)];
  const uint32_t n = uint32_t(sampleCount_);
  if (points.size() != n) {
    std::vector<uint32_t> indices(n);
    for (uint32_t i = 0; i < n; ++i) indices[i] = i;
    points.resize(n);
    fillSobolReversed(n, dimension, indices.data(), points.data());
  }
  return points.data();
}

float LowDiscrepancySampler::get1D() {
  if (hasPendingY_) {
    hasPendingY_ = false;
    return pendingY_;
  }
  Vec2 point = nextPoint();
  hasPendingY_ = true;
  pendingY_ = point.y;
  return point.x;
}

Vec2 LowDiscrepancySampler::get2D() { return nextPoint(); }

Vec2 LowDiscrepancySampler::nextPoint() {
  uint64_t hash = state_.nextDimensionHash();
  if (const DimensionTable* t = table(hash)) return {t->values[state_.index], t->values[sampleCount_ + state_.index]};
  return point2D(state_.dimension - 1, state_.index, uint32_t(sampleCount_), hash, progressive_);
}

int LowDiscrepancySampler::patternSize(int count) {
  int size = 1;
  while (size < count) size *= 2;
  return size;
}

std::shared_ptr<Object> makeLowDiscrepancySampler(const Properties& props) {
  SamplerParameters p = readSamplerParameters(props);
  return std::make_shared<LowDiscrepancySampler>(LowDiscrepancySampler::patternSize(p.sampleCount), p.seed);
}

}  // namespace columba
