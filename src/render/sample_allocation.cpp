#include "render/sample_allocation.h"

#include <algorithm>
#include <cmath>

namespace columba {

SamplePlan planSamples(const std::vector<PilotPixel>& pilot, int width, int height, const SamplePlanSettings& s) {
  const int n0 = s.pilotCount;
  const size_t pixels = size_t(width) * size_t(height);
  // Variance of one sample of each pixel from its pilot (unbiased estimate).
  std::vector<double> variance(pixels, 0.0);
  long long seen = 0;
  double luminanceSum = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    if (!pilot[i].seen) continue;
    ++seen;
    luminanceSum += pilot[i].sum / n0;
    if (n0 > 1) {
      double mean = pilot[i].sum / n0;
      variance[i] = std::max((pilot[i].sumSquares - n0 * mean * mean) / (n0 - 1), 0.0);
    }
  }
  SamplePlan plan;
  plan.counts.assign(pixels, 0);
  if (seen == 0) return plan;
  const double meanLuminance = luminanceSum / double(seen);

  // s_i from the seen neighbours' variances.
  std::vector<double> deviation(pixels, 0.0);
  double deviationSum = 0.0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      size_t i = size_t(y) * width + x;
      if (!pilot[i].seen) continue;
      double sum = 0.0;
      int neighbours = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int nx = x + dx, ny = y + dy;
          if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
          size_t j = size_t(ny) * width + nx;
          if (!pilot[j].seen) continue;
          sum += variance[j];
          ++neighbours;
        }
      deviation[i] = neighbours > 0 ? std::sqrt(sum / neighbours) : 0.0;
      deviationSum += deviation[i];
    }

  double budget = s.meanBudget * double(seen);
  if (s.targetError > 0.0 && meanLuminance > 0.0 && deviationSum > 0.0) {
    // (sum of s_i)^2 / B = seen * (targetError * mean luminance)^2, solved for B.
    double needed = deviationSum * deviationSum / (double(seen) * std::pow(s.targetError * meanLuminance, 2.0));
    budget = std::min(budget, needed);
  }
  const double rest = std::max(budget - double(n0) * double(seen), 0.0);
  double predictedVariance = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    if (!pilot[i].seen) continue;
    double share = deviationSum > 0.0 ? deviation[i] / deviationSum : 1.0 / double(seen);
    double extra = std::floor(rest * share + 0.5);
    int count = int(std::min(double(n0) + extra, double(std::max(s.maxPerPixel, n0))));
    plan.counts[i] = count;
    plan.total += count;
    predictedVariance += deviation[i] * deviation[i] / count;
  }
  if (meanLuminance > 0.0) plan.predictedRelativeError = std::sqrt(predictedVariance / double(seen)) / meanLuminance;
  return plan;
}

}  // namespace columba
