/*! plugin shape disk
The unit disk in the local xy plane, facing +z, with polar uv (radius, angle / 2π); a nested BSDF (default: `diffuse`) and optionally an `area` emitter.
Mitsuba 3: as Mitsuba 3's `disk`.
uses: media
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | places and sizes the disk | same |
| flip_normals | boolean | false | faces −z instead | same |
*/
#include "shapes/disk_shape.h"

#include "core/sampling.h"
#include "shapes/triangle_mesh.h"

namespace columba {

Vec2 DiskShape::uvAt(Vec2 local) const {
  float r = std::sqrt(local.x * local.x + local.y * local.y);
  float phi = std::atan2(local.y, local.x);
  return Vec2(r, (phi < 0 ? phi + kTwoPi : phi) * (0.5f * kInvPi));
}

std::pair<Vec2, Vec2> DiskShape::localPositionDerivatives(Vec2 local) const {
  // u = r: the radial unit vector; v = phi / (2 pi): 2 pi r along the circle.
  float r = std::sqrt(local.x * local.x + local.y * local.y);
  if (!(r > 0.0f)) return {Vec2(1, 0), Vec2(0, 0)};
  Vec2 radial(local.x / r, local.y / r);
  return {radial, Vec2(-local.y, local.x) * kTwoPi};
}

Vec2 DiskShape::sampleLocal(Vec2 u) const { return sampleConcentricDisk(u); }

std::shared_ptr<Object> makeDiskShape(const Properties& props) {
  auto shape = std::make_shared<DiskShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
