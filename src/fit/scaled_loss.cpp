#include "fit/scaled_loss.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace columba {

LossKind parseLossKind(const std::string& name) {
  if (name == "mse") return LossKind::MSE;
  if (name == "log") return LossKind::Log;
  if (name == "relative") return LossKind::Relative;
  throw std::runtime_error(fmt::format("--loss must be mse, log or relative, not '{}'", name));
}

ScaleMode parseScaleMode(const std::string& name) {
  if (name == "free") return ScaleMode::Free;
  if (name == "fixed") return ScaleMode::Fixed;
  throw std::runtime_error(fmt::format("--scale must be free or fixed, not '{}'", name));
}

const char* lossKindName(LossKind kind) {
  return kind == LossKind::MSE ? "mse" : kind == LossKind::Log ? "log" : "relative";
}

const char* scaleModeName(ScaleMode mode) { return mode == ScaleMode::Free ? "free" : "fixed"; }

ScaledLoss::ScaledLoss(std::vector<float> target, std::vector<float> weights, LossKind kind, ScaleMode mode)
    : target_(std::move(target)), weights_(std::move(weights)), kind_(kind), mode_(mode) {
  if (weights_.empty()) weights_.assign(target_.size(), 1.0f);
  if (weights_.size() != target_.size())
    throw std::runtime_error(
        fmt::format("the loss has {} weights for {} target values", weights_.size(), target_.size()));
  double magnitude = 0.0;
  for (size_t i = 0; i < target_.size(); ++i) {
    if (!std::isfinite(target_[i])) weights_[i] = 0.0f;  // unusable measurements carry no weight
    weightSum_ += weights_[i];
    if (weights_[i] > 0.0f) magnitude += weights_[i] * std::abs(target_[i]);
  }
  if (weightSum_ <= 0.0) throw std::runtime_error("the target has no finite value where the mask is set");
  offset_ = 0.01 * magnitude / weightSum_;
  if (offset_ <= 0.0) offset_ = 1e-6;
}

LossValue ScaledLoss::operator()(const std::vector<float>& model) const {
  if (model.size() != target_.size())
    throw std::runtime_error(fmt::format("the model has {} values, the target {}", model.size(), target_.size()));
  LossValue result;
  if (mode_ == ScaleMode::Free) {
    double mt = 0.0, mm = 0.0;
    for (size_t i = 0; i < model.size(); ++i)
      if (weights_[i] > 0.0f && std::isfinite(model[i])) {
        mt += weights_[i] * double(model[i]) * target_[i];
        mm += weights_[i] * double(model[i]) * model[i];
      }
    // A black model has no best scale; 1 leaves the loss at the target's own magnitude.
    result.scale = mm > 0.0 && mt > 0.0 ? mt / mm : 1.0;
  }
  double sum = 0.0;
  for (size_t i = 0; i < model.size(); ++i) {
    if (weights_[i] <= 0.0f) continue;
    const double t = target_[i];
    const double m = std::isfinite(model[i]) ? result.scale * model[i] : 0.0;
    double d = 0.0;
    switch (kind_) {
      case LossKind::MSE:
        d = m - t;
        break;
      case LossKind::Log:
        d = std::log(std::max(m, 0.0) + offset_) - std::log(std::max(t, 0.0) + offset_);
        break;
      case LossKind::Relative:
        d = (m - t) / (std::abs(t) + offset_);
        break;
    }
    sum += weights_[i] * d * d;
  }
  result.loss = sum / weightSum_;
  return result;
}

}  // namespace columba
