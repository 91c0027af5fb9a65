/*! plugin bsdf bumpmap
One nested BSDF on the surface displaced along its normal by scale × height (the nested texture), without moving the geometry: the shading normal is the cross product of the displaced surface's derivatives, from dp/du and dp/dv, which meshes and the analytic shapes give (on a feather the frame is left unperturbed).
Mitsuba 3: the same parameter and default; the normal is turned to the shading normal's side, where Mitsuba 3 uses the geometric normal's.
| parameter | type | default | meaning | Mitsuba 3 |
| scale | float | 1 | a factor on the height texture | same |
*/
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
