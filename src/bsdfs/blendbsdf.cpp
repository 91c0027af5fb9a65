/*! plugin bsdf blendbsdf
A blend of two nested BSDFs: (1 − weight) times the first plus weight times the second.
Mitsuba 3: the same parameter and default.
| parameter | type | default | meaning | Mitsuba 3 |
| weight | float or texture | 0.5 | the second BSDF's share, 0 to 1 | same |
*/
#include "bsdfs/blendbsdf.h"

#include <algorithm>

namespace columba {

float BlendBSDF::weightAt(const BSDFContext& ctx) const { return std::clamp(weight_.eval(ctx.point), 0.0f, 1.0f); }

Spectrum BlendBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const float weight = weightAt(ctx);
  return (1.0f - weight) * first_->eval(ctx, wi, wo, wl) + weight * second_->eval(ctx, wi, wo, wl);
}

float BlendBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const float weight = weightAt(ctx);
  return (1.0f - weight) * first_->pdf(ctx, wi, wo, wl) + weight * second_->pdf(ctx, wi, wo, wl);
}

std::optional<BSDFSample> BlendBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                            float uComponent, Vec2 u) const {
  const float weight = weightAt(ctx);
  bool second = uComponent >= 1.0f - weight;
  float choice = second ? weight : 1.0f - weight;
  float remaining = second ? (uComponent - (1.0f - weight)) / weight : uComponent / (1.0f - weight);
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
  const float weight = weightAt(ctx);
  return (1.0f - weight) * first_->passThrough(ctx, wi, wl) + weight * second_->passThrough(ctx, wi, wl);
}

std::shared_ptr<Object> makeBlendBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 2)
    throw InputError(props.location, "'blendbsdf' takes two nested BSDFs, not " + std::to_string(nested.size()));
  FloatParameter weight = readFloatParameter(props, "weight", 0.5f);
  if (!weight.isTextured() && !(weight.mean() >= 0.0f && weight.mean() <= 1.0f))
    throw props.error("weight", "must lie in [0, 1], not " + std::to_string(weight.mean()));
  return std::make_shared<BlendBSDF>(nested[0], nested[1], weight);
}

}  // namespace columba
