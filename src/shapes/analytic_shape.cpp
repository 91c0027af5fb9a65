#include "shapes/analytic_shape.h"

#include "shapes/embree_user_geometry.h"

namespace columba {

namespace {
void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  Vec3 lo, hi;
  shape->localBounds(lo, hi);
  Vec3 wlo(INFINITY, INFINITY, INFINITY), whi(-INFINITY, -INFINITY, -INFINITY);
  for (int c = 0; c < 8; ++c) {
    Vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
    Vec3 w = shape->toWorldPoint(corner);
    wlo = minv(wlo, w);
    whi = maxv(whi, w);
  }
  args->bounds_o->lower_x = wlo.x;
  args->bounds_o->lower_y = wlo.y;
  args->bounds_o->lower_z = wlo.z;
  args->bounds_o->upper_x = whi.x;
  args->bounds_o->upper_y = whi.y;
  args->bounds_o->upper_z = whi.z;
}

// `context` tells which instance, if any, the ray is traced through (intersection only).
template <bool occlusion>
void hitCallback(const AnalyticShape* shape, unsigned primID, unsigned geomID, const RTCIntersectContext* context,
                 RTCRay& ray, RTCHit* hit) {
  Vec3 o(ray.org_x, ray.org_y, ray.org_z), d(ray.dir_x, ray.dir_y, ray.dir_z);
  float t;
  if (!shape->intersectWorld(o, d, ray.tnear, ray.tfar, t)) return;
  if constexpr (occlusion) {
    ray.tfar = -INFINITY;
  } else {
    Vec3 ng = shape->worldNormal(o + d * t);
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

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
  if (args->N != 1 || !args->valid[0]) return;
  hitCallback<false>(static_cast<const AnalyticShape*>(args->geometryUserPtr), args->primID, args->geomID,
                     args->context, rh->ray, &rh->hit);
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  if (args->N != 1 || !args->valid[0]) return;
  auto* ray = reinterpret_cast<RTCRay*>(args->ray);
  hitCallback<true>(static_cast<const AnalyticShape*>(args->geometryUserPtr), args->primID, args->geomID, args->context,
                    *ray, nullptr);
}
}  // namespace

unsigned AnalyticShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  return attachUserGeometry(device, scene, 1, this, boundsCallback, intersectCallback, occludedCallback);
}

}  // namespace columba
