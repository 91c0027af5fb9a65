#include "film/filter_footprint.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace columba {

FilterFootprint::FilterFootprint(const ReconstructionFilter& filter)
    : radius_(filter.radius()), reach_(std::max(0, int(std::ceil(filter.radius() - 0.5f)))) {
  if (!(radius_ <= kMaxFilterRadius))
    throw std::invalid_argument(
        fmt::format("a reconstruction filter's radius must be at most {} pixels, not {}", kMaxFilterRadius, radius_));
  // Nodes over the squares of the pixels within reach: their edges, at half pixels, are nodes.
  const int steps = (2 * reach_ + 1) * kStepsPerPixel;
  tableStart_ = -(float(reach_) + 0.5f);
  // One node more than the squares span: an offset on the last node still has a node after it.
  table_.resize(size_t(steps) + 2);
  // Each node takes the filter just inside it, toward the centre, so that a filter cut off at its
  // radius (the box) keeps its value up to its edge.
  for (int i = 0; i <= steps + 1; ++i)
    table_[size_t(i)] = filter.eval((tableStart_ + float(i) / kStepsPerPixel) * (1.0f - 0x1p-20f));
  // Trapezoids over each pixel's steps: the exact mass of the linear pieces.
  for (int k = 0; k <= 2 * reach_; ++k) {
    double mass = 0.0;
    for (int i = k * kStepsPerPixel; i < (k + 1) * kStepsPerPixel; ++i)
      mass += 0.5 * (double(table_[size_t(i)]) + double(table_[size_t(i) + 1]));
    cellMass_.push_back(mass / kStepsPerPixel);
  }
}

FilterFootprint::AxisWeights FilterFootprint::axisWeights(int pixel, float position) const {
  // Pixels c whose centre c + 1/2 lies within the radius, and within reach of the sample's pixel.
  const int first = std::max(pixel - reach_, int(std::ceil(position - 0.5f - radius_)));
  const int last = std::min(pixel + reach_, int(std::floor(position - 0.5f + radius_)));
  AxisWeights axis;
  axis.first = first;
  axis.count = std::max(0, last - first + 1);
  // The offsets from successive centres are a whole pixel apart, so they share their place
  // between table nodes; the last pixel's offset is the smallest.
  const float t = (position - (float(last) + 0.5f) - tableStart_) * float(kStepsPerPixel);
  const int node = std::max(0, int(t));
  const float between = t - float(node);
  for (int i = 0; i < axis.count; ++i) {
    const float* at = &table_[size_t(node + (axis.count - 1 - i) * kStepsPerPixel)];
    axis.weights[i] = double(at[0] + between * (at[1] - at[0]));
  }
  return axis;
}

double FilterFootprint::massWithin(int pixel, int length) const {
  double mass = 0.0;
  for (int k = std::max(-reach_, -pixel); k <= std::min(reach_, length - 1 - pixel); ++k) mass += cellMass_[k + reach_];
  return mass;
}

}  // namespace columba
