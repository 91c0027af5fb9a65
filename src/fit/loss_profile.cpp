#include "fit/loss_profile.h"

#include <algorithm>
#include <numeric>

namespace columba {

namespace {

// The crossing of the threshold on one side (direction +1 or -1) of parameter `i`.
double crossing(size_t i, int direction, const FitParameter& p, const std::vector<double>& best, double threshold,
                EvaluationLog& log, LossProfile& profile, bool& atBound) {
  auto lossAt = [&](double value) {
    std::vector<double> x = best;
    x[i] = value;
    double loss = log.evaluate(x, "profile").loss;
    profile.values.push_back(value);
    profile.losses.push_back(loss);
    return loss;
  };
  const double range = p.upper - p.lower, bound = direction > 0 ? p.upper : p.lower;
  double inside = best[i];  // the farthest value known below the threshold
  for (double step = range / 256.0;; step *= 2.0) {
    double value = best[i] + direction * step;
    if ((value - bound) * direction >= 0.0) value = bound;
    if (lossAt(value) > threshold) {
      double outside = value;
      for (int k = 0; k < 2; ++k) {
        double middle = 0.5 * (inside + outside);
        (lossAt(middle) > threshold ? outside : inside) = middle;
      }
      atBound = false;
      return 0.5 * (inside + outside);
    }
    inside = value;
    if (value == bound) {
      atBound = true;
      return bound;
    }
  }
}

}  // namespace

std::vector<LossProfile> profileLoss(const std::vector<FitParameter>& parameters, double rise, EvaluationLog& log) {
  const std::vector<double> best = log.best().values;
  const double minimum = log.best().loss.loss;
  const double threshold = minimum * (1.0 + rise);
  std::vector<LossProfile> profiles(parameters.size());
  for (size_t i = 0; i < parameters.size(); ++i) {
    LossProfile& profile = profiles[i];
    profile.values.push_back(best[i]);
    profile.losses.push_back(minimum);
    profile.lower = crossing(i, -1, parameters[i], best, threshold, log, profile, profile.lowerAtBound);
    profile.upper = crossing(i, +1, parameters[i], best, threshold, log, profile, profile.upperAtBound);
    std::vector<size_t> order(profile.values.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return profile.values[a] < profile.values[b]; });
    LossProfile sorted = profile;
    for (size_t k = 0; k < order.size(); ++k) {
      sorted.values[k] = profile.values[order[k]];
      sorted.losses[k] = profile.losses[order[k]];
    }
    profile = sorted;
  }
  return profiles;
}

}  // namespace columba
