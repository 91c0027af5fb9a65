#include "bsdfs/bumpmap.h"

namespace columba {

Frame BumpMapBSDF::perturbedFrame(const BSDFContext& ctx) const {
  if (!(lengthSquared(cross(ctx.dpdu, ctx.dpdv)) > 0.0f)) return Frame();
  const Vec2 slope = height_->evalFloatGradient(ctx.point) * scale_;
  // In the local frame the normal is +z: the displaced surface's derivatives have z = the slopes.
  const Vec3 du(ctx.dpdu.x, ctx.dpdu.y, slope.x), dv(ctx.dpdv.x, ctx.dpdv.y, slope.y);
  Vec3 n = normalize(cross(du, dv));
  if (n.z < 0.0f) n = -n;
  return Frame::fromNormalAndS(n, du);
}

std::shared_ptr<Object> makeBumpMapBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 1)
    throw InputError(props.location, "'bumpmap' takes one nested BSDF, not " + std::to_string(nested.size()));
  auto height = props.child<Texture>();
  if (!height) throw InputError(props.location, "'bumpmap' needs a nested texture (the height)");
  return std::make_shared<BumpMapBSDF>(nested.front(), height, props.getFloat("scale", 1.0f));
}

}  // namespace columba
