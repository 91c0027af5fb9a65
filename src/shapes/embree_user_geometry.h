#pragma once
// Registers a shape's own exact intersector with Embree as user geometry.
#include <embree3/rtcore.h>

#include "core/vector.h"

namespace columba {

// Adds `primitiveCount` user primitives calling back with `userData`, commits the geometry
// and returns its ID in `scene`.
unsigned attachUserGeometry(RTCDevice device, RTCScene scene, unsigned primitiveCount, const void* userData,
                            RTCBoundsFunction bounds, RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded);

// Embree's intersect and occluded callbacks for user geometry whose user data is a `const Geometry*`
// answering, for the world ray o + t d (d not normalised):
//   bool intersectPrimitive(unsigned primID, const Vec3& o, const Vec3& d, float tmin, float tmax,
//                           float& t) const;   whether primitive primID is hit within (tmin, tmax),
//                                              and the nearest such t
//   Vec3 primitiveNormal(unsigned primID, const Vec3& worldPoint) const;   the unit geometric normal
//                                              at a hit, Embree's Ng
// `context` tells which instance, if any, the ray is traced through (intersection only).
template <class Geometry, bool occlusion>
void userGeometryHit(const Geometry* geometry, unsigned primID, unsigned geomID, const RTCIntersectContext* context,
                     RTCRay& ray, RTCHit* hit) {
  Vec3 o(ray.org_x, ray.org_y, ray.org_z), d(ray.dir_x, ray.dir_y, ray.dir_z);
  float t;
  if (!geometry->intersectPrimitive(primID, o, d, ray.tnear, ray.tfar, t)) return;
  if constexpr (occlusion) {
    ray.tfar = -INFINITY;
  } else {
    Vec3 ng = geometry->primitiveNormal(primID, o + d * t);
    ray.tfar = t;
    hit->Ng_x = ng.x;
    hit->Ng_y = ng.y;
    hit->Ng_z = ng.z;
    hit->u = 0;
    hit->v = 0;
    hit->primID = primID;
    hit->geomID = geomID;
    hit->instID[0] = context->instID[0];
  }
}

template <class Geometry>
void userGeometryIntersect(const RTCIntersectFunctionNArguments* args) {
  auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  if (args->N != 1 || !args->valid[0]) return;
  userGeometryHit<Geometry, false>(static_cast<const Geometry*>(args->geometryUserPtr), args->primID, args->geomID,
                                   args->context, rh->ray, &rh->hit);
}

template <class Geometry>
void userGeometryOccluded(const RTCOccludedFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  auto* ray = reinterpret_cast<RTCRay*>(args->ray);
  userGeometryHit<Geometry, true>(static_cast<const Geometry*>(args->geometryUserPtr), args->primID, args->geomID,
                                  args->context, *ray, nullptr);
}

}  // namespace columba
