#include "shapes/rectangle_shape.h"

#include "shapes/triangle_mesh.h"

namespace columba {

unsigned RectangleShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
  auto* corners = static_cast<Vec3*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(Vec3), 4));
  corners[0] = worldPoint(Vec2(-1.0f, -1.0f));
  corners[1] = worldPoint(Vec2(1.0f, -1.0f));
  corners[2] = worldPoint(Vec2(1.0f, 1.0f));
  corners[3] = worldPoint(Vec2(-1.0f, 1.0f));
  auto* quad = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), 1));
  for (unsigned i = 0; i < 4; ++i) quad[i] = i;
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

std::shared_ptr<Object> makeRectangleShape(const Properties& props) {
  auto shape = std::make_shared<RectangleShape>(props.getTransform("to_world"), props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  return shape;
}

}  // namespace columba
