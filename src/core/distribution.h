#pragma once
// Piecewise-constant 1D and 2D distributions (tabulated CDFs), for choosing triangles by area
// and environment-map pixels by luminance.
#include <vector>
#include "core/vector.h"

namespace columba {

class Distribution1D {
 public:
  Distribution1D() = default;
  // Weights must be non-negative with a positive sum.
  explicit Distribution1D(std::vector<float> weights);
  size_t size() const { return weights_.size(); }
  float total() const { return total_; }
  // Index drawn with probability weight/total; `u` is rescaled to [0, 1) for reuse.
  size_t sampleDiscrete(float u, float* rescaledU = nullptr) const;
  float discretePmf(size_t i) const { return weights_[i] / total_; }
  // Continuous position in [0, 1) and its density.
  float sampleContinuous(float u, float* pdf, size_t* index = nullptr) const;
  float continuousPdf(float x) const;

 private:
  std::vector<float> weights_;
  std::vector<double> cdf_;
  float total_ = 0.0f;
};

// Density over [0,1)^2 proportional to a width x height grid of non-negative weights.
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(const std::vector<float>& weights, int width, int height);
  Vec2 sample(Vec2 u, float* pdf) const;
  float pdf(Vec2 p) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Distribution1D> rows_;
  Distribution1D marginal_;
};

}  // namespace columba
