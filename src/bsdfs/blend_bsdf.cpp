#include "bsdfs/blend_bsdf.h"

namespace columba {

Spectrum BlendBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return (1.0f - weight_) * first_->eval(ctx, wi, wo, wl) + weight_ * second_->eval(ctx, wi, wo, wl);
}

float BlendBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return (1.0f - weight_) * first_->pdf(ctx, wi, wo, wl) + weight_ * second_->pdf(ctx, wi, wo, wl);
}

std::optional<BSDFSample> BlendBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                            float uComponent, Vec2 u) const {
  bool second = uComponent >= 1.0f - weight_;
  float choice = second ? weight_ : 1.0f - weight_;
  float remaining = second ? (uComponent - (1.0f - weight_)) / weight_ : uComponent / (1.0f - weight_);
  std::optional<BSDFSample> s = (second ? second_ : first_)->sample(ctx, wi, wl, std::min(remaining, 1.0f), u);
  if (!s) return s;
  if (s->delta) {
    s->pdf *= choice;
    return s;
  }
  s->pdf = pdf(ctx, wi, s->wo, wl);
  if (!(s->pdf > 0.0f)) return std::nullopt;
  s->weight = eval(ctx, wi, s->wo, wl) / s->pdf;
  return s;
}

Spectrum BlendBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  return (1.0f - weight_) * first_->passThrough(ctx, wi, wl) + weight_ * second_->passThrough(ctx, wi, wl);
}

std::shared_ptr<Object> makeBlendBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 2)
    throw InputError(props.location, "'blendbsdf' takes two nested BSDFs, not " + std::to_string(nested.size()));
  float weight = props.getFloat("weight", 0.5f);
  if (!(weight >= 0.0f && weight <= 1.0f))
    throw props.error("weight", "must lie in [0, 1], not " + std::to_string(weight));
  return std::make_shared<BlendBSDF>(nested[0], nested[1], weight);
}

}  // namespace columba
