#pragma once
// `disk`: the unit disk in the local xy plane, facing +z.
#include "core/properties.h"
#include "shapes/planar_shape.h"

namespace columba {

class DiskShape : public PlanarShape {
 public:
  DiskShape(const Transform& toWorld, bool flipNormals) : PlanarShape(toWorld, flipNormals, kPi) {}

 protected:
  bool contains(Vec2 local) const override { return local.x * local.x + local.y * local.y <= 1.0f; }
  // Polar coordinates: (radius, angle / 2 pi).
  Vec2 uvAt(Vec2 local) const override;
  std::pair<Vec2, Vec2> localPositionDerivatives(Vec2 local) const override;
  Vec2 sampleLocal(Vec2 u) const override;
};

std::shared_ptr<Object> makeDiskShape(const Properties& props);

}  // namespace columba
