#pragma once
// What a fit found, and the fit itself for any objective: the two optimiser stages, then the
// loss profiles that give each parameter its uncertainty.
#include <string>
#include <vector>
#include "fit/loss_profile.h"
#include "fit/optimizer.h"

namespace columba {

struct FitResult {
  std::vector<FitParameter> parameters;
  std::vector<double> values;  // fitted, one per parameter
  LossValue loss;              // at the fitted values, with the scale that gave it
  int evaluations = 0;         // by the optimiser (the start point included)
  double seconds = 0.0;        // the optimiser's
  double profileRise = 0.1;    // the intervals: where the loss stays below (1 + rise) x its minimum
  std::vector<LossProfile> profiles;
  int profileEvaluations = 0;
  double totalSeconds = 0.0;  // with the profiles
  std::vector<Evaluation> history;
  std::string globalAlgorithm, localAlgorithm;  // the NLopt algorithms of the two stages, as run
};

struct FitSettings {
  OptimizerSettings optimizer;
  double profileRise = 0.1;
  FitProgress progress;  // may be empty
};

// Throws std::invalid_argument naming the value, for what no fit can run with: no parameter, one
// varied twice or also held fixed (`fixed`: the names given values, a scene's -D variables), an
// evaluation budget below the parameters' count + 2, a time budget or rise that is not positive.
// What `columba fit` and Python's fit and fit_spectra check alike, before any evaluation.
void checkFitSettings(const std::vector<FitParameter>& parameters, const FitSettings& settings,
                      const std::vector<std::string>& fixed);

// Checks the settings (with nothing fixed), then fits.
FitResult runFit(const std::vector<FitParameter>& parameters, FitObjective objective, const FitSettings& settings);

}  // namespace columba
