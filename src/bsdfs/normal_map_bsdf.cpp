#include "bsdfs/normal_map_bsdf.h"

namespace columba {

namespace {
// Both directions on the same side of the surface in both frames.
bool sameSideInBoth(const Vec3& local, const Vec3& perturbed) { return cosTheta(local) * cosTheta(perturbed) > 0.0f; }
}  // namespace

Frame NormalMapBSDF::perturbedFrame(Vec2 uv) const {
  const Vec3 c = normals_->evalRGB(uv);
  const Vec3 n = Vec3(2.0f * c.x - 1.0f, 2.0f * c.y - 1.0f, 2.0f * c.z - 1.0f);
  if (!(lengthSquared(n) > 0.0f)) return Frame();
  return Frame::fromNormalAndS(normalize(n), Vec3(1, 0, 0));
}

Spectrum NormalMapBSDF::eval(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const Frame frame = perturbedFrame(ctx.uv);
  const Vec3 wiP = frame.toLocal(wi), woP = frame.toLocal(wo);
  if (!sameSideInBoth(wo, woP)) return Spectrum(0.0f);
  return nested_->eval(ctx, wiP, woP, wl);
}

float NormalMapBSDF::pdf(const BSDFContext& ctx, const Vec3& wi, const Vec3& wo, const Wavelengths& wl) const {
  const Frame frame = perturbedFrame(ctx.uv);
  const Vec3 wiP = frame.toLocal(wi), woP = frame.toLocal(wo);
  if (!sameSideInBoth(wo, woP)) return 0.0f;
  return nested_->pdf(ctx, wiP, woP, wl);
}

std::optional<BSDFSample> NormalMapBSDF::sample(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl,
                                                float uComponent, Vec2 u) const {
  const Frame frame = perturbedFrame(ctx.uv);
  std::optional<BSDFSample> s = nested_->sample(ctx, frame.toLocal(wi), wl, uComponent, u);
  if (!s) return s;
  const Vec3 woP = s->wo;
  s->wo = frame.toWorld(woP);
  if (!s->passThrough && !sameSideInBoth(s->wo, woP)) return std::nullopt;
  return s;
}

Spectrum NormalMapBSDF::passThrough(const BSDFContext& ctx, const Vec3& wi, const Wavelengths& wl) const {
  return nested_->passThrough(ctx, perturbedFrame(ctx.uv).toLocal(wi), wl);
}

std::shared_ptr<Object> makeNormalMapBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 1)
    throw InputError(props.location, "'normalmap' takes one nested BSDF, not " + std::to_string(nested.size()));
  auto texture = props.namedChild<Texture>("normalmap");
  if (!texture) throw InputError(props.location, "'normalmap' needs a texture named 'normalmap'");
  auto bitmap = std::dynamic_pointer_cast<const BitmapTexture>(texture);
  if (!bitmap || !bitmap->hasRawRGB())
    throw props.error("normalmap", "the normal map must be a colour bitmap read with raw=true");
  return std::make_shared<NormalMapBSDF>(nested.front(), bitmap);
}

}  // namespace columba
