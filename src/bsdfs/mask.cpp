/*! plugin bsdf mask
One nested BSDF on a fraction `opacity` of the surface (leaves, fences); the rest lets light through untouched, as a pass-through with weight 1 − opacity, for shadow rays too.
Mitsuba 3: the same parameter and default.
| parameter | type | default | meaning | Mitsuba 3 |
| opacity | float or texture | 0.5 | the fraction of the surface the nested BSDF covers, 0 to 1 | same |
*/
#include "bsdfs/mask.h"

#include <algorithm>

namespace columba {

float MaskBSDF::opacityAt(const BSDFContext& ctx) const { return std::clamp(opacity_.eval(ctx.point), 0.0f, 1.0f); }

Spectrum MaskBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  return opacityAt(ctx) * nested_->eval(ctx, wi, wo, wl);
}

float MaskBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  float nested = nested_->pdf(ctx, wi, wo, wl);
  return ctx.passThroughByCaller ? nested : opacityAt(ctx) * nested;
}

std::optional<BSDFSample> MaskBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                           float uComponent, Vec2 u) const {
  const float opacity = opacityAt(ctx), transparency = 1.0f - opacity;
  if (ctx.passThroughByCaller) {
    // Always the nested BSDF: f scales by the opacity, the density does not.
    std::optional<BSDFSample> s = nested_->sample(ctx, wi, wl, uComponent, u);
    if (s) s->weight *= opacity;
    return s;
  }
  if (uComponent < transparency) {
    BSDFSample s;
    s.wo = -wi;
    s.weight = Spectrum(1.0f);
    s.pdf = transparency;
    s.delta = s.passThrough = true;
    return s;
  }
  // The nested BSDF with what uComponent has left; f and pdf both scale by the opacity.
  std::optional<BSDFSample> s = nested_->sample(ctx, wi, wl, (uComponent - transparency) / opacity, u);
  if (s) s->pdf *= opacity;
  return s;
}

Spectrum MaskBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  const float opacity = opacityAt(ctx);
  Spectrum through(1.0f - opacity);
  if (nested_->hasPassThrough()) through += opacity * nested_->passThrough(ctx, wi, wl);
  return through;
}

std::shared_ptr<Object> makeMaskBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 1)
    throw InputError(props.location, "'mask' takes one nested BSDF, not " + std::to_string(nested.size()));
  FloatParameter opacity = readFloatParameter(props, "opacity", 0.5f);
  if (!opacity.isTextured() && !(opacity.mean() >= 0.0f && opacity.mean() <= 1.0f))
    throw props.error("opacity", "must lie in [0, 1], not " + std::to_string(opacity.mean()));
  return std::make_shared<MaskBSDF>(nested.front(), opacity);
}

}  // namespace columba
