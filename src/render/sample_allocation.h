#pragma once
// Adaptive sampling's plan: how many samples each pixel gets after a pilot, so that the image's
// mean squared error is smallest for the budget. With s_i the standard deviation of one sample of
// pixel i, n_i samples leave it an error variance s_i^2 / n_i, and the sum of those over the image
// for a total of B samples is smallest at n_i proportional to s_i (Lagrange): the sum is then
// (sum of s_i)^2 / B. Every pixel keeps its pilot samples and the rest of the budget goes in
// proportion to s_i.
//
// s_i is estimated from the pilot samples of the pixel's eight neighbours, not its own: its count
// then does not depend on its own samples, so the pixel's mean stays unbiased (choosing more
// samples where the pixel's own pilot happened to be bright would bias it). The plan depends only
// on the pilot sums, which do not depend on threads: the render stays bit-identical for any
// thread count.
#include <vector>

namespace columba {

// One pixel's pilot: the sum and sum of squares of its samples' luminance; `seen` is false for
// pixels the camera does not see (they take no samples).
struct PilotPixel {
  double sum = 0.0, sumSquares = 0.0;
  bool seen = false;
};

struct SamplePlan {
  std::vector<int> counts;  // per pixel, row by row: the pilot's and the rest (0 where unseen)
  long long total = 0;
  // The relative RMSE the plan predicts: sqrt(mean of s_i^2 / n_i) / mean luminance (0 when the
  // image is black).
  double predictedRelativeError = 0.0;
};

struct SamplePlanSettings {
  int pilotCount = 0;         // samples every seen pixel already has
  double meanBudget = 0.0;    // samples per seen pixel on average, the pilot's included
  double targetError = 0.0;   // > 0: spend only what reaching this predicted relative RMSE takes
  int maxPerPixel = 1 << 24;  // no pixel gets more
};

SamplePlan planSamples(const std::vector<PilotPixel>& pilot, int width, int height, const SamplePlanSettings& s);

}  // namespace columba
