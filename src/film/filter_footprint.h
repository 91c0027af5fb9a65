#pragma once
// What a sample adds to the pixels around it. A sample at film position x (in pixels) adds its
// value times weight(x) = f(x - cx) f(y - cy) to every pixel whose centre c its separable filter
// f reaches; this class gives those weights, and the filter's mass over each pixel's square,
// which normalises the sums.
//
// With n samples drawn uniformly in every pixel, each weighted 1/n, a pixel's expected sum is the
// integral of f(x - c) L(x) over the film, and its expected weight the mass of f(x - c) over the
// film: Mitsuba's filtered image, whose pixel is their ratio. Columba divides by the expected
// weight, summed from the filter's mass over the film's pixels, rather than by the sampled
// weights: then an image is linear in its samples, so renders of sample ranges merge exactly,
// and with each pixel's samples weighted 1 / their count, a pixel's expected value does not depend
// on how many samples each of its neighbours took.
//
// The filter as splatted is the filter's values at steps of 1 / kStepsPerPixel pixel, linear in
// between: a table lookup instead of an exponential per weight. The masses are that function's,
// so the estimate stays unbiased for it; it differs from the filter by about 1e-5 of its peak
// (Gaussian, stddev 0.5), and follows the box exactly, and the tent where its kinks lie on steps
// (radii that are multiples of 1/256 pixel, such as Mitsuba's default 1).
#include <vector>
#include "film/reconstruction_filter.h"

namespace columba {

class FilterFootprint {
 public:
  explicit FilterFootprint(const ReconstructionFilter& filter);

  // How many pixels on each side of its own a sample may reach: ceil(radius - 1/2).
  int reach() const { return reach_; }
  static constexpr int kStepsPerPixel = 256;
  // The pixels [first, first + count) along one axis that a sample at coordinate `position` of
  // pixel `pixel` reaches, and their weights (count <= 2 reach + 1).
  static constexpr int kMaxSpan = 2 * kMaxFilterReach + 1;
  struct AxisWeights {
    int first = 0, count = 0;
    double weights[kMaxSpan];  // in double precision, as splats are summed
  };
  AxisWeights axisWeights(int pixel, float position) const;
  // The splatted filter's mass over the squares of the pixels [0, length) of an axis, seen from
  // the centre of `pixel`: 1 except within reach() of the film's edges.
  double massWithin(int pixel, int length) const;

 private:
  float radius_;
  int reach_;
  float tableStart_;              // the offset of table_[0]: -(reach + 1/2)
  std::vector<float> table_;      // the filter at tableStart_ + i / kStepsPerPixel
  std::vector<double> cellMass_;  // the splatted filter's mass over [k - 1/2, k + 1/2], k = -reach .. reach
};

}  // namespace columba
