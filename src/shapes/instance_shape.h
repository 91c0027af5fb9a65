#pragma once
// `instance`: a shapegroup placed in the scene by an affine `to_world`, applied on top of the
// group's shapes' own transforms. Embree traces the group's scene through an instance geometry;
// a hit is resolved in the group's space and its interaction carried back to the scene's.
#include <memory>
#include "core/properties.h"
#include "core/transform.h"
#include "shapes/shape.h"
#include "shapes/shape_group.h"

namespace columba {

class InstanceShape : public Shape {
 public:
  // Embree inverts the matrix of `toWorld` itself; the interaction inverts it too, so that both
  // agree to rounding whatever inverse `toWorld` carries.
  // `values`: per-point BSDF parameters this copy gives in place of its shapes' own (a feather's
  // cortex thickness, so that copies of one feather differ in colour).
  InstanceShape(std::shared_ptr<const ShapeGroup> group, const Transform& toWorld, SurfaceAttributes values = {})
      : group_(std::move(group)), toWorld_(toWorld.matrix()), toGroup_(toWorld_.inverse()), values_(values) {}
  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  // `hit.geomID` is the shape hit within the group (Embree's geomID under instID[0]).
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  size_t primitiveCount() const override { return group_->primitiveCount(); }
  bool anyBSDF(const std::function<bool(const BSDF&)>& test) const override { return group_->anyBSDF(test); }

 private:
  std::shared_ptr<const ShapeGroup> group_;
  Transform toWorld_, toGroup_;
  SurfaceAttributes values_;
};

// <shape type="instance">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeInstanceShape(const Properties& props);

}  // namespace columba
