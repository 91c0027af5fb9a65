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
    const FitParameter& p = parameters[i];
    profile.values.push_back(best[i]);
    profile.losses.push_back(minimum);
    double lower = crossing(i, -1, p, best, threshold, log, profile, profile.lowerAtBound);
    double upper = crossing(i, +1, p, best, threshold, log, profile, profile.upperAtBound);
    for (int k = 0; k < kProfileScanPoints; ++k) {
      std::vector<double> x = best;
      x[i] = p.lower + (p.upper - p.lower) * double(k) / double(kProfileScanPoints - 1);
      profile.values.push_back(x[i]);
      profile.losses.push_back(log.evaluate(x, "profile").loss);
    }
    std::vector<size_t> order(profile.values.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return profile.values[a] < profile.values[b]; });
    LossProfile sorted = profile;
    for (size_t k = 0; k < order.size(); ++k) {
      sorted.values[k] = profile.values[order[k]];
      sorted.losses[k] = profile.losses[order[k]];
    }
    profile = sorted;
    // The stretches below the threshold; the optimum's keeps the bisected crossings, the others
    // end halfway to the first value above it.
    const std::vector<double>& v = profile.values;
    const std::vector<double>& l = profile.losses;
    for (size_t k = 0; k < v.size();) {
      if (l[k] > threshold) {
        ++k;
        continue;
      }
      ProfileSolution s{v[k], l[k], k == 0 ? v[k] : 0.5 * (v[k - 1] + v[k]), 0.0};
      size_t end = k;
      for (; end < v.size() && l[end] <= threshold; ++end)
        if (l[end] < s.loss) s.value = v[end], s.loss = l[end];
      s.upper = end == v.size() ? v[end - 1] : 0.5 * (v[end - 1] + v[end]);
      if (s.lower <= best[i] && best[i] <= s.upper) {
        s.lower = std::min(s.lower, lower);
        s.upper = std::max(s.upper, upper);
      }
      profile.solutions.push_back(s);
      k = end;
    }
    profile.lower = profile.solutions.empty() ? lower : std::min(lower, profile.solutions.front().lower);
    profile.upper = profile.solutions.empty() ? upper : std::max(upper, profile.solutions.back().upper);
    profile.lowerAtBound = profile.lower <= p.lower;
    profile.upperAtBound = profile.upper >= p.upper;
  }
  return profiles;
}

}  // namespace columba
