/*! plugin sampler multijitter
Correlated multi-jittered samples (Kensler 2013): in 2D a pixel's samples lie one per cell of a columns × rows grid (`sample_count` rounded up to a near-square grid) and at the same time one per each of the thin strata along either axis. Every dimension has its own pattern seed, so dimensions are not correlated; 1D dimensions are jittered strata in a random order.
Mitsuba 3: the same parameters and defaults.
uses: sampler
| parameter | type | default | meaning | Mitsuba 3 |
| jitter | boolean | true | random points within the cells; false: their centres | same |
*/
#include "samplers/multijitter_sampler.h"

#include <cmath>
#include "samplers/hashed_permutation.h"
#include "samplers/sampler_parameters.h"

namespace columba {

void MultijitterSampler::startPixelSample(int px, int py, int sampleIndex, uint64_t seed) {
  state_.start(px, py, sampleIndex, hashCombine(seed, seed_), uint32_t(sampleCount_));
  state_.seedRandomness();
}

float MultijitterSampler::get1D() {
  uint32_t n = uint32_t(sampleCount_);
  uint32_t stratum = permutationElement(state_.index, n, uint32_t(state_.nextDimensionHash()));
  return clampToUnitInterval((stratum + double(offset())) / n);
}

Vec2 MultijitterSampler::get2D() {
  uint64_t hash = state_.nextDimensionHash(), hash2 = mixBits(hash);
  uint32_t m = uint32_t(columns_), n = uint32_t(rows_);
  // Cell (column, row) of the coarse grid; inside it, the sub-column is a permutation of the
  // row and the sub-row a permutation of the column, shared by all cells ("correlated"), which
  // puts exactly one sample in each thin stratum along x and along y.
  uint32_t s = permutationElement(state_.index, m * n, uint32_t(hash));
  uint32_t column = s % m, row = s / m;
  uint32_t subColumn = permutationElement(row, n, uint32_t(hash >> 32));
  uint32_t subRow = permutationElement(column, m, uint32_t(hash2));
  double dx = offset(), dy = offset();
  return {clampToUnitInterval((column + (subColumn + dx) / n) / m), clampToUnitInterval((row + (subRow + dy) / m) / n)};
}

namespace {
// A near-square grid of at least `count` cells.
std::unique_ptr<MultijitterSampler> multijitterFor(int count, bool jitter, uint64_t seed) {
  int rows = std::max(1, int(std::sqrt(double(count))));
  int columns = (count + rows - 1) / rows;
  return std::make_unique<MultijitterSampler>(columns, rows, jitter, seed);
}
}  // namespace

std::unique_ptr<Sampler> MultijitterSampler::withSampleCount(int count) const {
  return multijitterFor(count, jitter_, seed_);
}

std::shared_ptr<Object> makeMultijitterSampler(const Properties& props) {
  SamplerParameters p = readSamplerParameters(props);
  return multijitterFor(p.sampleCount, props.getBool("jitter", true), p.seed);
}

}  // namespace columba
