#pragma once
// Registers a shape's own exact intersector with Embree as user geometry.
#include <embree3/rtcore.h>

namespace columba {

// Adds `primitiveCount` user primitives calling back with `userData`, commits the geometry
// and returns its ID in `scene`.
unsigned attachUserGeometry(RTCDevice device, RTCScene scene, unsigned primitiveCount, const void* userData,
                            RTCBoundsFunction bounds, RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded);

}  // namespace columba
