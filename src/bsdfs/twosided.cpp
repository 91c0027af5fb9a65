/*! plugin bsdf twosided
A two-sided adapter around one or two nested BSDFs: the first for light arriving above the surface, the second (or the first again), mirrored through the surface, for light below it. Meant for reflective BSDFs: nested BSDFs that transmit would scatter into the wrong side.
Mitsuba 3: as Mitsuba 3's `twosided`.
*/
#include "bsdfs/twosided.h"

namespace columba {

namespace {
// Mirror through the surface: the back side seen as a front side.
Vec3 flip(const Vec3& w) { return Vec3(w.x, w.y, -w.z); }
}  // namespace

Spectrum TwoSidedBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) > 0.0f) return front_->eval(ctx, wi, wo, wl);
  if (cosTheta(wi) < 0.0f) return back_->eval(ctx, flip(wi), flip(wo), wl);
  return Spectrum(0.0f);
}

float TwoSidedBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  if (cosTheta(wi) > 0.0f) return front_->pdf(ctx, wi, wo, wl);
  if (cosTheta(wi) < 0.0f) return back_->pdf(ctx, flip(wi), flip(wo), wl);
  return 0.0f;
}

std::optional<BSDFSample> TwoSidedBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                               float uComponent, Vec2 u) const {
  if (cosTheta(wi) > 0.0f) return front_->sample(ctx, wi, wl, uComponent, u);
  if (cosTheta(wi) == 0.0f) return std::nullopt;
  auto s = back_->sample(ctx, flip(wi), wl, uComponent, u);
  if (s) s->wo = flip(s->wo);
  return s;
}

Spectrum TwoSidedBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  if (cosTheta(wi) >= 0.0f) return front_->passThrough(ctx, wi, wl);
  return back_->passThrough(ctx, flip(wi), wl);
}

std::shared_ptr<Object> makeTwoSidedBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.empty() || nested.size() > 2)
    throw InputError(props.location, "'twosided' takes one or two nested BSDFs, not " + std::to_string(nested.size()));
  return std::make_shared<TwoSidedBSDF>(nested.front(), nested.back());
}

}  // namespace columba
