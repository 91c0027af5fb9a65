#pragma once
// `rectangle`: the square [-1, 1]^2 in the local xy plane, facing +z; uv = ((x + 1) / 2, (y + 1) / 2).
#include "core/properties.h"
#include "shapes/planar_shape.h"

namespace columba {

class RectangleShape : public PlanarShape {
 public:
  RectangleShape(const Transform& toWorld, bool flipNormals) : PlanarShape(toWorld, flipNormals, 4.0f) {}

 protected:
  bool contains(Vec2 local) const override { return std::abs(local.x) <= 1.0f && std::abs(local.y) <= 1.0f; }
  Vec2 uvAt(Vec2 local) const override { return Vec2(0.5f * (local.x + 1.0f), 0.5f * (local.y + 1.0f)); }
  std::pair<Vec2, Vec2> localPositionDerivatives(Vec2) const override { return {Vec2(2, 0), Vec2(0, 2)}; }
  Vec2 sampleLocal(Vec2 u) const override { return Vec2(2.0f * u.x - 1.0f, 2.0f * u.y - 1.0f); }
};

std::shared_ptr<Object> makeRectangleShape(const Properties& props);

}  // namespace columba
