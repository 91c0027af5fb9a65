#include "fit/fit_result.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace columba {

void checkFitSettings(const std::vector<FitParameter>& parameters, const FitSettings& settings,
                      const std::vector<std::string>& fixed) {
  if (parameters.empty()) throw std::invalid_argument("give at least one parameter to vary, as 'NAME=LO:HI[:START]'");
  for (size_t i = 0; i < parameters.size(); ++i) {
    const std::string& name = parameters[i].name;
    for (size_t j = 0; j < i; ++j)
      if (parameters[j].name == name) throw std::invalid_argument(fmt::format("'{}' is varied twice", name));
    if (std::find(fixed.begin(), fixed.end(), name) != fixed.end())
      throw std::invalid_argument(fmt::format("'{}' is both held fixed (a define) and varied", name));
  }
  const int evaluations = settings.optimizer.maxEvaluations;
  if (evaluations < int(parameters.size()) + 2)
    throw std::invalid_argument(
        fmt::format("the budget of {} evaluations (max evals) is too small for {} "
                    "parameter{}: it needs at least {}",
                    evaluations, parameters.size(), parameters.size() == 1 ? "" : "s", parameters.size() + 2));
  if (!(settings.optimizer.maxSeconds > 0.0))
    throw std::invalid_argument(
        fmt::format("the time budget (max seconds) must be positive, not {}", settings.optimizer.maxSeconds));
  if (!(settings.profileRise > 0.0))
    throw std::invalid_argument(fmt::format("rise must be positive, not {}", settings.profileRise));
}

FitResult runFit(const std::vector<FitParameter>& parameters, FitObjective objective, const FitSettings& settings) {
  checkFitSettings(parameters, settings, {});
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
  result.globalAlgorithm = settings.optimizer.globalAlgorithm;
  result.localAlgorithm = localAlgorithm(parameters.size());
  return result;
}

}  // namespace columba
