#include "fit/optimizer.h"

#include <nlopt.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

namespace columba {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// The stages work in the unit cube, so that one step size and tolerance suit every parameter.
struct UnitCube {
  const std::vector<FitParameter>& parameters;
  std::vector<double> toValues(const std::vector<double>& u) const {
    std::vector<double> v(u.size());
    for (size_t i = 0; i < u.size(); ++i) {
      const FitParameter& p = parameters[i];
      v[i] = p.lower + std::clamp(u[i], 0.0, 1.0) * (p.upper - p.lower);
    }
    return v;
  }
  std::vector<double> toUnit(const std::vector<double>& v) const {
    std::vector<double> u(v.size());
    for (size_t i = 0; i < v.size(); ++i)
      u[i] = (v[i] - parameters[i].lower) / (parameters[i].upper - parameters[i].lower);
    return u;
  }
};

struct StageContext {
  const UnitCube* cube;
  EvaluationLog* log;
  const char* stage;
  std::exception_ptr* failure = nullptr;
  nlopt_opt opt = nullptr;
};

// NLopt is a C library: exceptions must not cross it, so they are kept and NLopt is stopped.
double stageObjective(unsigned n, const double* u, double* /*gradient*/, void* data) {
  auto* context = static_cast<StageContext*>(data);
  try {
    return context->log->evaluate(context->cube->toValues(std::vector<double>(u, u + n)), context->stage).loss;
  } catch (...) {
    *context->failure = std::current_exception();
    nlopt_force_stop(context->opt);
    return HUGE_VAL;
  }
}

// One NLopt run from `start` within the budgets. Whatever NLopt returns (a roundoff limit, the
// budget spent, a failure) is not an error of the fit: the log keeps the best point either way.
void runStage(nlopt_algorithm algorithm, const char* stage, const UnitCube& cube, std::vector<double> start,
              int evaluations, double seconds, EvaluationLog& log) {
  if (evaluations <= 0 || seconds <= 0.0) return;
  const unsigned n = unsigned(start.size());
  nlopt_opt opt = nlopt_create(algorithm, n);
  if (!opt) throw std::runtime_error("NLopt could not create its optimiser");
  const std::vector<double> zeros(n, 0.0), ones(n, 1.0);
  nlopt_set_lower_bounds(opt, zeros.data());
  nlopt_set_upper_bounds(opt, ones.data());
  StageContext context{&cube, &log, stage};
  nlopt_set_min_objective(opt, stageObjective, &context);
  nlopt_set_maxeval(opt, evaluations);
  nlopt_set_maxtime(opt, seconds);
  if (algorithm == NLOPT_LN_BOBYQA || algorithm == NLOPT_LN_NELDERMEAD) {
    nlopt_set_initial_step1(opt, 0.05);  // 5 % of each range: about the global stage's final cells
    nlopt_set_xtol_abs1(opt, 1e-5);
    nlopt_set_ftol_rel(opt, 1e-9);
  }
  double value = 0.0;
  // An exception from the objective (a scene that fails to load) stops NLopt and is rethrown.
  std::exception_ptr failure;
  context.failure = &failure;
  context.opt = opt;
  nlopt_optimize(opt, start.data(), &value);
  nlopt_destroy(opt);
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

EvaluationLog::EvaluationLog(FitObjective objective, FitProgress progress)
    : objective_(std::move(objective)), progress_(std::move(progress)), startTime_(now()) {}

double EvaluationLog::seconds() const { return now() - startTime_; }

LossValue EvaluationLog::evaluate(const std::vector<double>& values, const std::string& stage) {
  Evaluation e;
  e.index = int(history_.size()) + 1;
  e.stage = stage;
  e.values = values;
  e.loss = objective_(values);
  // NLopt's stages compare numbers: a non-finite loss is the worst possible, not an exception.
  if (!std::isfinite(e.loss.loss)) e.loss.loss = HUGE_VAL;
  e.seconds = seconds();
  history_.push_back(e);
  if (history_.size() == 1 || e.loss.loss < history_[bestIndex_].loss.loss) bestIndex_ = history_.size() - 1;
  if (progress_) progress_(history_.back(), best());
  return e.loss;
}

namespace {

// The best evaluations of the global stage that lie at least `separation` (unit-cube distance)
// from each better one: the starts of the local stage, best first.
std::vector<std::vector<double>> distinctBest(const std::vector<Evaluation>& history, const UnitCube& cube,
                                              size_t count, double separation) {
  std::vector<const Evaluation*> sorted;
  for (const Evaluation& e : history) sorted.push_back(&e);
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const Evaluation* a, const Evaluation* b) { return a->loss.loss < b->loss.loss; });
  std::vector<std::vector<double>> starts;
  for (const Evaluation* e : sorted) {
    std::vector<double> u = cube.toUnit(e->values);
    bool distinct = true;
    for (const std::vector<double>& s : starts) {
      double d2 = 0.0;
      for (size_t i = 0; i < u.size(); ++i) d2 += (u[i] - s[i]) * (u[i] - s[i]);
      distinct = distinct && d2 >= separation * separation;
    }
    if (distinct) starts.push_back(u);
    if (starts.size() == count) break;
  }
  return starts;
}

}  // namespace

std::string localAlgorithm(size_t parameterCount) { return parameterCount > 1 ? "LN_BOBYQA" : "LN_NELDERMEAD"; }

void minimise(const std::vector<FitParameter>& parameters, const OptimizerSettings& settings, EvaluationLog& log) {
  UnitCube cube{parameters};
  std::vector<double> start;
  for (const FitParameter& p : parameters) start.push_back(p.startValue());
  log.evaluate(start, "start");
  nlopt_srand(1);  // the stochastic global algorithms (CRS, ISRES...) draw the same points every run
  const int globalEvaluations = int(std::floor(settings.globalShare * (settings.maxEvaluations - 1)));
  const nlopt_algorithm global = nlopt_algorithm_from_string(settings.globalAlgorithm.c_str());
  if (int(global) < 0 || settings.globalAlgorithm.rfind("GN_", 0) != 0)
    throw std::runtime_error("'" + settings.globalAlgorithm +
                             "' is not a global derivative-free NLopt algorithm (GN_...)");
  runStage(global, "global", cube, cube.toUnit(start), globalEvaluations,
           settings.globalShare * settings.maxSeconds - log.seconds(), log);
  const nlopt_algorithm local = nlopt_algorithm_from_string(localAlgorithm(parameters.size()).c_str());
  // Interference makes the loss multimodal in the film thickness: the local stage starts from
  // the best few distinct basins the global stage found, each with an equal share of what is left.
  const std::vector<std::vector<double>> starts =
      distinctBest(log.history(), cube, size_t(std::max(settings.localStarts, 1)), 0.15);
  for (size_t k = 0; k < starts.size(); ++k) {
    const int left = settings.maxEvaluations - int(log.history().size());
    const double secondsLeft = settings.maxSeconds - log.seconds();
    const double share = 1.0 / double(starts.size() - k);
    runStage(local, "local", cube, starts[k], int(left * share), secondsLeft * share, log);
  }
}

}  // namespace columba
