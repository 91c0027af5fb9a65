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

}  // namespace

unsigned AnalyticShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  return attachUserGeometry(device, scene, 1, this, boundsCallback, userGeometryIntersect<AnalyticShape>,
                            userGeometryOccluded<AnalyticShape>);
}

}  // namespace columba
