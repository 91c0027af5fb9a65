#include "shapes/disk_shape.h"

#include "core/sampling.h"
#include "shapes/triangle_mesh.h"

namespace columba {

Vec2 DiskShape::uvAt(Vec2 local) const {
  float r = std::sqrt(local.x * local.x + local.y * local.y);
  float phi = std::atan2(local.y, local.x);
  return Vec2(r, (phi < 0 ? phi + kTwoPi : phi) * (0.5f * kInvPi));
}

Vec2 DiskShape::sampleLocal(Vec2 u) const { return sampleConcentricDisk(u); }

std::shared_ptr<Object> makeDiskShape(const Properties& props) {
  auto shape = std::make_shared<DiskShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
