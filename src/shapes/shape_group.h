#pragma once
// `shapegroup`: shapes declared once and rendered only through `instance`s of the group. They
// keep their own to_world and BSDFs; their "world" is the group's space, which each instance
// places in the scene. As in Mitsuba, a group holds no emitters, groups or instances.
#include <embree3/rtcore.h>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>
#include "core/properties.h"
#include "shapes/shape.h"

namespace columba {

class ShapeGroup : public Object {
 public:
  explicit ShapeGroup(std::vector<std::shared_ptr<Shape>> shapes) : shapes_(std::move(shapes)) {}
  ~ShapeGroup() override;
  ShapeGroup(const ShapeGroup&) = delete;
  ShapeGroup& operator=(const ShapeGroup&) = delete;

  // The group's shapes as a committed Embree scene of `device`: built at the first call for that
  // device and shared by every instance of the group there.
  RTCScene embreeScene(RTCDevice device) const;
  // The shape with Embree geometry ID `geomID` in the group's scene.
  const Shape& shape(unsigned geomID) const { return *shapes_[geomID]; }
  size_t primitiveCount() const;
  // Whether the BSDF of any of the group's shapes passes `test`.
  bool anyBSDF(const std::function<bool(const BSDF&)>& test) const;

 private:
  std::vector<std::shared_ptr<Shape>> shapes_;  // indexed by geometry ID in the group's scene
  // The scene last built and its device, both retained: a device is not freed, and so its
  // address not reused, while the group still knows it.
  mutable std::mutex embreeMutex_;
  mutable RTCDevice embreeDevice_ = nullptr;
  mutable RTCScene embreeScene_ = nullptr;
};

// <shape type="shapegroup">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeShapeGroup(const Properties& props);

}  // namespace columba
