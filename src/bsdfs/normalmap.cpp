/*! plugin bsdf normalmap
One nested BSDF seen through shading normals read from a texture of raw triples: the triple c at a point gives the normal 2c − 1 in the frame of dp/du and the shading normal; the nested BSDF is evaluated in the frame around it whose x axis is the closest to dp/du. As in Mitsuba, directions on different sides of the two surfaces get no value.
Mitsuba 3: the same parameter; the texture must give raw triples.
| parameter | type | default | meaning | Mitsuba 3 |
| normalmap | texture | required | a `bitmap` read with `raw`, a 3-component `rawconstant` or a `mesh_attribute` | same |
*/
#include "bsdfs/normalmap.h"

namespace columba {

Frame NormalMapBSDF::perturbedFrame(const BSDFContext& ctx) const {
  const Vec3 c = normals_->evalTriple(ctx.point);
  const Vec3 n = Vec3(2.0f * c.x - 1.0f, 2.0f * c.y - 1.0f, 2.0f * c.z - 1.0f);
  if (!(lengthSquared(n) > 0.0f)) return Frame();
  return Frame::fromNormalAndS(normalize(n), Vec3(1, 0, 0));
}

std::shared_ptr<Object> makeNormalMapBSDF(const Properties& props) {
  auto nested = props.children<BSDF>();
  if (nested.size() != 1)
    throw InputError(props.location, "'normalmap' takes one nested BSDF, not " + std::to_string(nested.size()));
  auto texture = props.namedChild<Texture>("normalmap");
  if (!texture) throw InputError(props.location, "'normalmap' needs a texture named 'normalmap'");
  if (!texture->givesTriples())
    throw props.error("normalmap",
                      "the normal map must give raw triples: a colour bitmap read with raw=true, a rawconstant or a "
                      "mesh_attribute");
  return std::make_shared<NormalMapBSDF>(nested.front(), texture);
}

}  // namespace columba
