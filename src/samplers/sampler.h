#pragma once
// Sample generators. A sampler is cloned per tile and restarted for every pixel sample, with
// its state derived only from (pixel, sample index, seed): images do not depend on threads.
#include <cstdint>
#include <memory>
#include "core/object.h"
#include "core/vector.h"

namespace columba {

class Sampler : public Object {
 public:
  explicit Sampler(int sampleCount) : sampleCount_(sampleCount) {}
  int sampleCount() const { return sampleCount_; }
  virtual std::unique_ptr<Sampler> clone() const = 0;
  // The same sampler with a pattern for `count` samples per pixel, rounded as its plug-in rounds
  // sample_count (Mitsuba's set_sample_count): a render of `count` samples stratifies them
  // together, where the first `count` of a larger pattern would be a random subset of it.
  virtual std::unique_ptr<Sampler> withSampleCount(int count) const = 0;
  // The same sampler with a pattern whose every power-of-two prefix of a pixel's samples is
  // stratified by itself, for renders that take a pixel's samples a part at a time (adaptive
  // sampling's pilot, then the rest). Samplers without such a pattern return a copy of themselves:
  // a part of their pattern is then a random subset of it.
  virtual std::unique_ptr<Sampler> withProgressivePattern() const { return clone(); }
  virtual void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) = 0;
  // The next dimensions of the current sample, in [0, 1).
  virtual float get1D() = 0;
  virtual Vec2 get2D() = 0;

 protected:
  int sampleCount_;
};

}  // namespace columba
