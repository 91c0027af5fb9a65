#include "shapes/embree_user_geometry.h"

namespace columba {

unsigned attachUserGeometry(RTCDevice device, RTCScene scene, unsigned primitiveCount, const void* userData,
                            RTCBoundsFunction bounds, RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, primitiveCount);
  // Embree's API takes a mutable pointer; the callbacks only read through it.
  rtcSetGeometryUserData(geom, const_cast<void*>(userData));
  rtcSetGeometryBoundsFunction(geom, bounds, nullptr);
  rtcSetGeometryIntersectFunction(geom, intersect);
  rtcSetGeometryOccludedFunction(geom, occluded);
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

}  // namespace columba
