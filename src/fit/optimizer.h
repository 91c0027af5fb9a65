#pragma once
// Bounded minimisation of an expensive, deterministic objective with NLopt: a global stage
// (CRS2-LM by default, or DIRECT, ...: they need no start and sample the whole box, so every
// interference order of the film gets looked at) followed by local derivative-free searches
// (BOBYQA, or Nelder-Mead for one parameter) from its best distinct points, each within its
// share of a budget of evaluations and seconds.
#include <functional>
#include <string>
#include <vector>
#include "fit/fit_parameter.h"
#include "fit/scaled_loss.h"

namespace columba {

struct OptimizerSettings {
  int maxEvaluations = 300;
  double maxSeconds = 120.0;
  // Share of both budgets the global stage may use; the local stage gets what is left.
  double globalShare = 0.5;
  // Local searches, from the best points of the global stage that are at least 0.15 apart in
  // the unit cube of the bounds.
  int localStarts = 3;
  // The global stage's NLopt algorithm, by NLopt's name (GN_DIRECT, GN_DIRECT_L, GN_CRS2_LM, ...).
  std::string globalAlgorithm = "GN_CRS2_LM";
};

struct Evaluation {
  int index = 0;      // 1-based, in the order evaluated
  std::string stage;  // "start", "global", "local" or "profile"
  std::vector<double> values;
  LossValue loss;
  double seconds = 0;  // since the fit began
};

// Parameter values to their loss (and the scale that gave it).
using FitObjective = std::function<LossValue(const std::vector<double>&)>;
// Called after every evaluation with it and the best one so far.
using FitProgress = std::function<void(const Evaluation& latest, const Evaluation& best)>;

// Records every evaluation of an objective and the best so far; shared by the optimiser and the
// loss profiles, so that the history holds both.
class EvaluationLog {
 public:
  EvaluationLog(FitObjective objective, FitProgress progress);
  LossValue evaluate(const std::vector<double>& values, const std::string& stage);
  const std::vector<Evaluation>& history() const { return history_; }
  const Evaluation& best() const { return history_[bestIndex_]; }
  double seconds() const;

 private:
  FitObjective objective_;
  FitProgress progress_;
  std::vector<Evaluation> history_;
  size_t bestIndex_ = 0;
  double startTime_;
};

// The local stage's NLopt algorithm for this many parameters: LN_BOBYQA, or LN_NELDERMEAD for one
// (NLopt's BOBYQA needs two dimensions or more).
std::string localAlgorithm(size_t parameterCount);

// Evaluates the start point, then runs the two stages; the best evaluation is in log.best().
void minimise(const std::vector<FitParameter>& parameters, const OptimizerSettings& settings, EvaluationLog& log);

}  // namespace columba
