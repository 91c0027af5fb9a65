#pragma once
// The uncertainty of each fitted parameter from a 1-D slice of the loss through the optimum (the
// other parameters held at their fitted values), over the parameter's whole bounds: every value
// where the loss stays below (1 + rise) times the optimum's is admitted by the data. Where the
// slice dips below that threshold in several places, each dip is a solution and the interval
// spans all of them; a parameter the data do not constrain gets an interval reaching its bounds.
#include <vector>
#include "fit/fit_parameter.h"
#include "fit/optimizer.h"

namespace columba {

// A stretch of the slice below the threshold, and the value where its loss is least.
struct ProfileSolution {
  double value = 0.0, loss = 0.0;
  double lower = 0.0, upper = 0.0;
};

struct LossProfile {
  std::vector<double> values, losses;               // the slice's evaluations, sorted by value
  double lower = 0.0, upper = 0.0;                  // the interval: from the lowest to the highest solution's ends
  bool lowerAtBound = false, upperAtBound = false;  // the loss never rose enough on that side
  std::vector<ProfileSolution> solutions;           // by value; the optimum's among them
};

// Evaluations of the slice over each parameter's bounds besides those around the optimum.
inline constexpr int kProfileScanPoints = 33;

// Walks out from the best point of `log` on each side of each parameter in steps doubling from
// 1/256 of its range until the loss exceeds the threshold (or the bound is reached), bisecting
// the crossing twice; then evaluates the slice at kProfileScanPoints values evenly over the
// bounds, so that dips away from the optimum are found (each to the grid's resolution).
// Evaluations are logged with stage "profile".
std::vector<LossProfile> profileLoss(const std::vector<FitParameter>& parameters, double rise, EvaluationLog& log);

}  // namespace columba
