/*! plugin sampler stratified
Jittered stratified samples (as pbrt-v4's stratified sampler): in every dimension a pixel's samples fall one per stratum (1D: `sample_count` strata; 2D: a grid of resolution × resolution, `sample_count` rounded up to a square), and each dimension assigns strata to samples by its own random permutation, so dimensions are not correlated.
Mitsuba 3: the same parameters and defaults; `sample_count` is rounded up to a square as Mitsuba 3 does.
uses: sampler
| parameter | type | default | meaning | Mitsuba 3 |
| jitter | boolean | true | a random point in each stratum; false: its centre | same |
*/
#include "samplers/stratified_sampler.h"

#include "samplers/hashed_permutation.h"
#include "samplers/sampler_parameters.h"

namespace columba {

void StratifiedSampler::startPixelSample(int px, int py, int sampleIndex, uint64_t seed) {
  state_.start(px, py, sampleIndex, hashCombine(seed, seed_), uint32_t(sampleCount_));
  state_.seedRandomness();
}

float StratifiedSampler::get1D() {
  uint32_t n = uint32_t(sampleCount_);
  uint32_t stratum = permutationElement(state_.index, n, uint32_t(state_.nextDimensionHash()));
  return clampToUnitInterval((stratum + double(offset())) / n);
}

Vec2 StratifiedSampler::get2D() {
  uint32_t n = uint32_t(sampleCount_), res = uint32_t(resolution_);
  uint32_t stratum = permutationElement(state_.index, n, uint32_t(state_.nextDimensionHash()));
  double dx = offset(), dy = offset();
  return {clampToUnitInterval((stratum % res + dx) / res), clampToUnitInterval((stratum / res + dy) / res)};
}

int StratifiedSampler::resolutionFor(int count) {
  int resolution = 1;
  while (resolution * resolution < count) ++resolution;
  return resolution;
}

std::shared_ptr<Object> makeStratifiedSampler(const Properties& props) {
  SamplerParameters p = readSamplerParameters(props);
  bool jitter = props.getBool("jitter", true);
  return std::make_shared<StratifiedSampler>(StratifiedSampler::resolutionFor(p.sampleCount), jitter, p.seed);
}

}  // namespace columba
