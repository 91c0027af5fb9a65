#include "shapes/instance_shape.h"

namespace columba {

unsigned InstanceShape::addToEmbree(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geom, group_->embreeScene(device));
  const auto& m = toWorld_.matrix().m;
  float rows[12];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) rows[4 * r + c] = float(m[r][c]);
  rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

SurfaceInteraction InstanceShape::interaction(const Ray& ray, const HitRecord& hit) const {
  // The ray as Embree traced it in the group: an affine map keeps its parameter t.
  Ray groupRay = ray;
  groupRay.o = toGroup_.point(ray.o);
  groupRay.d = toGroup_.vector(ray.d);
  SurfaceInteraction si = group_->shape(hit.geomID).interaction(groupRay, hit);
  si.p = toWorld_.point(si.p);
  si.ng = normalize(toWorld_.normal(si.ng));
  // As Mitsuba: the normal by the inverse transpose, s (dp/du) as a vector, t rebuilt from both.
  si.shading = Frame::fromNormalAndS(normalize(toWorld_.normal(si.shading.n)), toWorld_.vector(si.shading.s));
  si.dpdu = toWorld_.vector(si.dpdu);
  si.dpdv = toWorld_.vector(si.dpdv);
  return si;
}

std::shared_ptr<Object> makeInstanceShape(const Properties& props) {
  auto groups = props.children<ShapeGroup>();
  if (groups.size() != 1)
    throw InputError(props.location, "an instance needs exactly one shapegroup (a <ref> to its id), not " +
                                         std::to_string(groups.size()));
  Transform toWorld = props.getTransform("to_world");
  const auto& m = toWorld.matrix().m;
  if (m[3][0] != 0.0 || m[3][1] != 0.0 || m[3][2] != 0.0 || m[3][3] != 1.0)
    throw props.error("to_world", "an instance's transform must be affine (last row 0, 0, 0, 1)");
  return std::make_shared<InstanceShape>(groups.front(), toWorld);
}

}  // namespace columba
