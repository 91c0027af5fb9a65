/*! plugin sampler independent
Uniform random samples, independent across dimensions, samples and pixels; the default sampler of every sensor.
Mitsuba 3: as Mitsuba 3's `independent`.
uses: sampler
*/
#include "samplers/independent_sampler.h"

#include "samplers/sampler_parameters.h"

namespace columba {

void IndependentSampler::startPixelSample(int px, int py, int sampleIndex, uint64_t seed) {
  state_.start(px, py, sampleIndex, hashCombine(seed, seed_), uint32_t(sampleCount_));
  state_.seedRandomness();
}

float IndependentSampler::get1D() { return state_.rng.nextFloat(); }

Vec2 IndependentSampler::get2D() {
  float x = state_.rng.nextFloat();
  float y = state_.rng.nextFloat();
  return {x, y};
}

std::shared_ptr<Object> makeIndependentSampler(const Properties& props) {
  SamplerParameters p = readSamplerParameters(props);
  return std::make_shared<IndependentSampler>(p.sampleCount, p.seed);
}

}  // namespace columba
