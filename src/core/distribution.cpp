#include "core/distribution.h"

#include <algorithm>
#include <stdexcept>

namespace columba {

Distribution1D::Distribution1D(std::vector<float> weights) : weights_(std::move(weights)) {
  if (weights_.empty()) throw std::invalid_argument("empty distribution");
  cdf_.resize(weights_.size() + 1, 0.0);
  for (size_t i = 0; i < weights_.size(); ++i) {
    if (!(weights_[i] >= 0.0f) || !std::isfinite(weights_[i]))
      throw std::invalid_argument("invalid distribution weight");
    cdf_[i + 1] = cdf_[i] + weights_[i];
  }
  total_ = float(cdf_.back());
  if (!(total_ > 0.0f)) throw std::invalid_argument("distribution weights sum to zero");
  for (double& c : cdf_) c /= cdf_.back();
}

size_t Distribution1D::sampleDiscrete(float u, float* rescaledU) const {
  size_t i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(u)) - cdf_.begin());
  i = std::clamp<size_t>(i, 1, weights_.size()) - 1;
  while (weights_[i] == 0.0f && i + 1 < weights_.size()) ++i;  // never return an empty bin
  if (rescaledU) {
    double width = cdf_[i + 1] - cdf_[i];
    *rescaledU = width > 0 ? std::min(float((u - cdf_[i]) / width), kOneMinusEpsilon) : 0.0f;
  }
  return i;
}

float Distribution1D::sampleContinuous(float u, float* pdf, size_t* index) const {
  float du;
  size_t i = sampleDiscrete(u, &du);
  if (index) *index = i;
  if (pdf) *pdf = weights_[i] / total_ * float(weights_.size());
  return std::min((float(i) + du) / float(weights_.size()), kOneMinusEpsilon);
}

float Distribution1D::continuousPdf(float x) const {
  size_t i = std::min(size_t(std::max(x, 0.0f) * weights_.size()), weights_.size() - 1);
  return weights_[i] / total_ * float(weights_.size());
}

Distribution2D::Distribution2D(const std::vector<float>& weights, int width, int height)
    : width_(width), height_(height) {
  std::vector<float> rowTotals(height);
  rows_.reserve(height);
  for (int y = 0; y < height; ++y) {
    std::vector<float> row(weights.begin() + size_t(y) * width, weights.begin() + size_t(y + 1) * width);
    float sum = 0;
    for (float w : row) sum += w;
    rowTotals[y] = sum;
    if (sum == 0.0f) std::fill(row.begin(), row.end(), 1.0f);  // unreachable row, kept valid
    rows_.emplace_back(std::move(row));
  }
  marginal_ = Distribution1D(std::move(rowTotals));
}

Vec2 Distribution2D::sample(Vec2 u, float* pdf) const {
  float pdfY, pdfX;
  size_t row;
  float y = marginal_.sampleContinuous(u.y, &pdfY, &row);
  float x = rows_[row].sampleContinuous(u.x, &pdfX);
  if (pdf) *pdf = pdfX * pdfY;
  return {x, y};
}

float Distribution2D::pdf(Vec2 p) const {
  size_t row = std::min(size_t(std::max(p.y, 0.0f) * height_), size_t(height_ - 1));
  return marginal_.continuousPdf(p.y) * rows_[row].continuousPdf(p.x);
}

}  // namespace columba
