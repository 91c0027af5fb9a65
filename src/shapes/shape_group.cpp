/*! plugin shape shapegroup
Shapes declared once (feathers included, with their own `to_world` and BSDFs) for `instance`s to place; a group is not rendered by itself. As in Mitsuba, a group holds no emitters (nor shapes with area emitters), no groups and no instances; nor shapes that bound media.
Mitsuba 3: as Mitsuba 3's `shapegroup`.
*/
#include "shapes/shape_group.h"

#include <algorithm>

#include <stdexcept>
#include "emitters/emitter.h"
#include "shapes/instance_shape.h"

namespace columba {

ShapeGroup::~ShapeGroup() {
  if (embreeScene_) rtcReleaseScene(embreeScene_);
  if (embreeDevice_) rtcReleaseDevice(embreeDevice_);
}

RTCScene ShapeGroup::embreeScene(RTCDevice device) const {
  std::lock_guard<std::mutex> lock(embreeMutex_);
  if (embreeDevice_ == device) return embreeScene_;
  RTCScene scene = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
  for (size_t i = 0; i < shapes_.size(); ++i)
    if (shapes_[i]->addToEmbree(device, scene) != i) {
      rtcReleaseScene(scene);
      throw std::logic_error("Embree geometry IDs are expected in insertion order");
    }
  rtcCommitScene(scene);
  // The instances that use a previous device's scene keep it alive themselves.
  if (embreeScene_) rtcReleaseScene(embreeScene_);
  if (embreeDevice_) rtcReleaseDevice(embreeDevice_);
  rtcRetainDevice(device);
  embreeDevice_ = device;
  embreeScene_ = scene;
  return scene;
}

size_t ShapeGroup::primitiveCount() const {
  size_t n = 0;
  for (const auto& s : shapes_) n += s->primitiveCount();
  return n;
}

bool ShapeGroup::anyBSDF(const std::function<bool(const BSDF&)>& test) const {
  return std::any_of(shapes_.begin(), shapes_.end(), [&](const auto& s) { return s->anyBSDF(test); });
}

std::shared_ptr<Object> makeShapeGroup(const Properties& props) {
  // Embree instances one level deep, as Mitsuba does.
  if (auto nested = props.children<ShapeGroup>(); !nested.empty())
    throw InputError(props.childLocation(*nested.front()), "a shapegroup cannot contain another shapegroup");
  if (auto emitters = props.children<Emitter>(); !emitters.empty())
    throw InputError(props.childLocation(*emitters.front()),
                     "a shapegroup cannot contain emitters: Columba, like Mitsuba, does not instance emitters");
  std::vector<std::shared_ptr<Shape>> shapes = props.children<Shape>();
  for (const auto& shape : shapes) {
    if (std::dynamic_pointer_cast<InstanceShape>(shape))
      throw InputError(props.childLocation(*shape), "a shapegroup cannot contain an instance");
    if (shape->emitter)
      throw InputError(props.childLocation(*shape),
                       "a shape in a shapegroup cannot carry an area emitter: Columba, like Mitsuba, does not "
                       "instance emitters");
    if (shape->interior || shape->exterior)
      throw InputError(props.childLocation(*shape), "a shape in a shapegroup cannot bound a medium");
  }
  return std::make_shared<ShapeGroup>(std::move(shapes));
}

}  // namespace columba
