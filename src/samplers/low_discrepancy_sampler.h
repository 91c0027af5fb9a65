#pragma once
// Low-discrepancy samples: Owen-scrambled Sobol points, served a 2D point at a time.
//
// The first four points of a sample are one Owen-scrambled Sobol sequence in eight dimensions:
// sample index i of a pixel takes point i of the sequence in every one of them, so the points are
// stratified jointly, not only each by itself. Each point takes two of the sequence's dimensions,
// chosen so that the points that matter most stay well stratified in 2D: point k is a (t, 2)-
// sequence with the t below, over every power-of-two count from 4 to 512 samples (only dimensions
// 0 and 1 together reach t = 0 at every count).
//   point 0 (in a render: the wavelengths and the first vertex's component choice): dimensions
//     3 and 4, t <= 2;
//   point 1 (the position in the pixel): dimensions 1 and 2, t <= 1;
//   point 2 (the first vertex's emitter or BSDF sample): dimensions 0 and 6, t <= 1;
//   point 3: dimensions 5 and 7, t <= 2.
// The dimensions are chosen for the lowest t of the points that matter most (against the padded
// pattern below for all points: docs/performance.md, "Sample patterns and wavelengths").
//
// Later points are padded (pbrt-v4's PaddedSobolSampler): each is the (0, 2)-sequence of
// dimensions 0 and 1, scrambled with its own seed, and which sample index gets which of its points
// is a random permutation per point, so they are not correlated with each other or with the
// first four.
//
// 1D requests are served in pairs from one 2D point: a 1D request takes x of a new point and the
// next 1D request, whenever it comes, takes its y. In a render the wavelengths (the first 1D
// request) pair with the first vertex's component choice, which for the barbule BSDF is the point
// across the cross-section, which lowers the variance against separate 1D sequences (Mitsuba's
// ldsampler; docs/performance.md, "Sample patterns and wavelengths").
//
// Any aligned block of 2^k sample indices of the first four points is itself a net with the same
// t (the sequence's property). For the padded points the progressive pattern
// (withProgressivePattern) scrambles the index's bits from the most significant down in place of
// the permutation, which maps every aligned block of 2^k sample indices onto an aligned block of
// the sequence, a (0, k, 2)-net. It pairs the points less independently (a little more variance,
// docs/performance.md), so only adaptive sampling, whose pilot and rest are such blocks, uses it.
//
// The renderer draws a pixel's samples one after another, and every sample asks for the same
// first points: those are computed for all of the pixel's samples at once, the first time the
// pixel asks for them, in a loop the compiler vectorises; the first four points' unscrambled
// sequence is the same for every pixel and is computed once. The values are the same as one at a
// time.
#include <array>
#include <memory>
#include <vector>
#include "samplers/pixel_sample_state.h"
#include "samplers/sampler.h"
#include "samplers/sobol.h"

namespace columba {

class Properties;

class LowDiscrepancySampler : public Sampler {
 public:
  // sampleCount must be a power of two.
  LowDiscrepancySampler(int sampleCount, uint64_t seed, bool progressive = false)
      : Sampler(sampleCount), seed_(seed), progressive_(progressive) {}
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<LowDiscrepancySampler>(*this); }
  std::unique_ptr<Sampler> withSampleCount(int count) const override {
    return std::make_unique<LowDiscrepancySampler>(patternSize(count), seed_, progressive_);
  }
  std::unique_ptr<Sampler> withProgressivePattern() const override {
    return std::make_unique<LowDiscrepancySampler>(sampleCount_, seed_, true);
  }
  // The power of two at or above `count`.
  static int patternSize(int count);
  void startPixelSample(int px, int py, int sampleIndex, uint64_t seed) override;
  float get1D() override;
  Vec2 get2D() override;

  // Point `point` of sample `index` (below sampleCount) one at a time, without the per-pixel tables;
  // dimensionHash is PixelSampleState's for that point.
  static Vec2 point2D(uint32_t point, uint32_t index, uint32_t sampleCount, uint64_t dimensionHash, bool progressive);

  // The first points of a sample and their Sobol dimensions (see above).
  static constexpr uint32_t kSobolPoints = 4;
  static constexpr std::array<std::array<int, 2>, kSobolPoints> kSobolPointDimensions = {
      {{3, 4}, {1, 2}, {0, 6}, {5, 7}}};

 private:
  // A dimension's values for every sample index of the current pattern: all x, then all y.
  struct DimensionTable {
    uint64_t generation = 0;  // PixelSampleState::patternGeneration() it was filled for
    std::vector<float> values;
  };
  static constexpr uint32_t kTabulatedDimensions = 8;
  static constexpr int kMaxTabulatedSamples = 4096;

  // The table of the dimension about to be drawn, filled if stale; null when not tabulated.
  const DimensionTable* table(uint64_t dimensionHash) {
    const uint32_t d = state_.dimension - 1;  // nextDimensionHash() has moved on
    if (d >= kTabulatedDimensions || sampleCount_ > kMaxTabulatedSamples) return nullptr;
    DimensionTable& t = tables_[d];
    if (t.generation != state_.patternGeneration()) fill(t, d, dimensionHash);
    return &t;
  }
  void fill(DimensionTable& t, uint32_t point, uint64_t dimensionHash);
  // The Sobol sequence's first sampleCount points in `dimension`, bit-reversed and not scrambled:
  // the same for every pixel, so computed once.
  const uint32_t* sequence(int dimension);
  // The next dimension's point (get2D, and the pairs get1D serves).
  Vec2 nextPoint();

  uint64_t seed_;
  bool progressive_;
  bool hasPendingY_ = false;  // a 1D request took x of a point whose y is next
  float pendingY_ = 0.0f;
  PixelSampleState state_;
  std::array<DimensionTable, kTabulatedDimensions> tables_;
  std::array<std::vector<uint32_t>, kSobolDimensions> sequences_;
  std::vector<uint32_t> scratch_;
};

// <sampler type="ldsampler">: its parameters are in docs/reference/samplers.md.
std::shared_ptr<Object> makeLowDiscrepancySampler(const Properties& props);

}  // namespace columba
