#pragma once
// The distance between a model (a render, or modelled spectra) and a measurement whose exposure
// may be unknown: the model is first multiplied by one global scale, in closed form.
#include <string>
#include <vector>

namespace columba {

enum class LossKind {
  MSE,       // mean of (s m - t)^2
  Log,       // mean of (log(s m + e) - log(t + e))^2
  Relative,  // mean of ((s m - t) / (|t| + e))^2
};
enum class ScaleMode {
  Free,   // s = <m, t> / <m, m> over the weighted values (least squares), the exposure unknown
  Fixed,  // s = 1, the measurement calibrated
};
// "mse", "log", "relative" / "free", "fixed"; throws std::runtime_error naming the value.
LossKind parseLossKind(const std::string& name);
ScaleMode parseScaleMode(const std::string& name);
const char* lossKindName(LossKind kind);
const char* scaleModeName(ScaleMode mode);

struct LossValue {
  double loss = 0.0;
  double scale = 1.0;
};

class ScaledLoss {
 public:
  // `weights` (one per value, 0 leaves a value out; empty: all 1). The offset e of the log and
  // relative losses is 1 % of the weighted mean of |target|, so that dark values do not dominate.
  ScaledLoss(std::vector<float> target, std::vector<float> weights, LossKind kind, ScaleMode mode);
  // `model` has one value per target value; non-finite model values count as a mismatch of the
  // target's magnitude.
  LossValue operator()(const std::vector<float>& model) const;
  const std::vector<float>& target() const { return target_; }

 private:
  std::vector<float> target_, weights_;
  LossKind kind_;
  ScaleMode mode_;
  double offset_ = 0.0;
  double weightSum_ = 0.0;
};

}  // namespace columba
