#include "fit/fit_result.h"

namespace columba {

FitResult runFit(const std::vector<FitParameter>& parameters, FitObjective objective, const FitSettings& settings) {
  EvaluationLog log(std::move(objective), settings.progress);
  minimise(parameters, settings.optimizer, log);
  FitResult result;
  result.parameters = parameters;
  // The optimum is the optimiser's; a profile point that happens to be lower does not move it, so
  // that the intervals stay centred on the reported values.
  const Evaluation best = log.best();
  result.values = best.values;
  result.loss = best.loss;
  result.evaluations = int(log.history().size());
  result.seconds = log.seconds();
  result.profileRise = settings.profileRise;
  result.profiles = profileLoss(parameters, settings.profileRise, log);
  result.profileEvaluations = int(log.history().size()) - result.evaluations;
  result.totalSeconds = log.seconds();
  result.history = log.history();
  return result;
}

}  // namespace columba
