#include "bsdfs/perturbed_frame_bsdf.h"

namespace columba {

namespace {
// A direction on the same side of the surface in both frames.
bool sameSideInBoth(const Vec3& local, const Vec3& perturbed) { return cosTheta(local) * cosTheta(perturbed) > 0.0f; }
}  // namespace

Spectrum PerturbedFrameBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const Frame frame = perturbedFrame(ctx);
  const Vec3 woP = frame.toLocal(wo);
  if (!sameSideInBoth(wo, woP)) return Spectrum(0.0f);
  return nested_->eval(ctx, frame.toLocal(wi), woP, wl);
}

float PerturbedFrameBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const Frame frame = perturbedFrame(ctx);
  const Vec3 woP = frame.toLocal(wo);
  if (!sameSideInBoth(wo, woP)) return 0.0f;
  return nested_->pdf(ctx, frame.toLocal(wi), woP, wl);
}

std::optional<BSDFSample> PerturbedFrameBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                     float uComponent, Vec2 u) const {
  const Frame frame = perturbedFrame(ctx);
  std::optional<BSDFSample> s = nested_->sample(ctx, frame.toLocal(wi), wl, uComponent, u);
  if (!s) return s;
  const Vec3 woP = s->wo;
  s->wo = frame.toWorld(woP);
  if (!s->passThrough && !sameSideInBoth(s->wo, woP)) return std::nullopt;
  return s;
}

Spectrum PerturbedFrameBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  return nested_->passThrough(ctx, perturbedFrame(ctx).toLocal(wi), wl);
}

}  // namespace columba
