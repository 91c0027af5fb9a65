#pragma once
// The uncertainty of each fitted parameter from a 1-D slice of the loss through the optimum (the
// other parameters held at their fitted values): the interval around the fitted value where the
// loss stays below (1 + rise) times its minimum. A parameter the data do not constrain gets an
// interval reaching its bounds.
#include <vector>
#include "fit/fit_parameter.h"
#include "fit/optimizer.h"

namespace columba {

struct LossProfile {
  std::vector<double> values, losses;               // the slice's evaluations, sorted by value
  double lower = 0.0, upper = 0.0;                  // the interval
  bool lowerAtBound = false, upperAtBound = false;  // the loss never rose enough on that side
};

// Walks out from the best point of `log` on each side of each parameter in steps doubling from
// 1/256 of its range until the loss exceeds the threshold (or the bound is reached), then
// bisects the crossing twice. Evaluations are logged with stage "profile".
std::vector<LossProfile> profileLoss(const std::vector<FitParameter>& parameters, double rise, EvaluationLog& log);

}  // namespace columba
