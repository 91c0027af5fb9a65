/*! plugin shape cylinder
The open tube (no end caps) of `radius` around the segment from `p0` to `p1`, then `to_world`, with uv = (angle / 2π, position along the axis); a nested BSDF (default: `diffuse`) and optionally an `area` emitter, which needs a `to_world` that keeps the tube round (no shear, the same scale across the axis).
Mitsuba 3: the same parameters and defaults.
uses: media
| parameter | type | default | meaning | Mitsuba 3 |
| p0 | point | (0, 0, 0) | one end of the axis | same |
| p1 | point | (0, 0, 1) | the other end; not `p0` | same |
| radius | float | 1 | the radius; positive | same |
| to_world | transform | identity | applied after the tube is built | same |
| flip_normals | boolean | false | normals point inward | same |
*/
#include "shapes/cylinder_shape.h"

#include "core/frame.h"
#include "shapes/triangle_mesh.h"

namespace columba {

CylinderShape::CylinderShape(const Transform& toWorld, bool flipNormals) : AnalyticShape(toWorld), flip_(flipNormals) {
  Vec3 ax = toWorld_.vector(Vec3(1, 0, 0)), ay = toWorld_.vector(Vec3(0, 1, 0)), az = toWorld_.vector(Vec3(0, 0, 1));
  float r = length(ax), tolerance = 1e-5f * r;
  area_ = kTwoPi * r * length(az);
  round_ = std::abs(length(ay) - r) < tolerance && std::abs(dot(ax, ay)) < tolerance * r &&
           std::abs(dot(ax, az)) < tolerance * length(az) && std::abs(dot(ay, az)) < tolerance * length(az);
}

bool CylinderShape::intersectWorld(const Vec3& worldO, const Vec3& worldD, float tmin, float tmax, float& t) const {
  Vec3 o = toLocalPoint(worldO), d = toLocalVector(worldD);
  // |(o + t d)_xy|^2 = 1 in double precision, then the nearer root within the tube's length.
  double a = double(d.x) * d.x + double(d.y) * d.y;
  double b = 2.0 * (double(o.x) * d.x + double(o.y) * d.y);
  double c = double(o.x) * o.x + double(o.y) * o.y - 1.0;
  double t0, t1;
  if (!solveQuadratic(a, b, c, t0, t1)) return false;
  for (double root : {t0, t1}) {
    double z = double(o.z) + root * d.z;
    if (root > tmin && root < tmax && z >= 0.0 && z <= 1.0) {
      t = float(root);
      return true;
    }
  }
  return false;
}

SurfaceInteraction CylinderShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  Vec3 local = toLocalPoint(ray.at(hit.t));
  float radial = std::sqrt(local.x * local.x + local.y * local.y);
  if (radial > 0.0f) local = Vec3(local.x / radial, local.y / radial, local.z);  // back onto the tube
  si.p = toWorldPoint(local);
  si.ng = toWorldNormal(localNormal(local));
  float phi = std::atan2(local.y, local.x);
  si.uv = Vec2((phi < 0 ? phi + kTwoPi : phi) * (0.5f * kInvPi), local.z);
  si.dpdu = toWorld_.vector(Vec3(-local.y, local.x, 0) * kTwoPi);
  si.dpdv = toWorld_.vector(Vec3(0, 0, 1));
  si.shading = Frame::fromNormalAndS(si.ng, toWorld_.vector(Vec3(-local.y, local.x, 0)));  // dp/du
  return si;
}

PositionSample CylinderShape::samplePosition(Vec2 u, bool withTexturePoint) const {
  float phi = kTwoPi * u.y;
  Vec3 local(std::cos(phi), std::sin(phi), u.x);
  PositionSample ps;
  ps.p = toWorldPoint(local);
  ps.n = toWorldNormal(localNormal(local));
  if (withTexturePoint) ps.point = Vec2(u.y, u.x);  // (phi / 2 pi, height), as hits give it
  ps.pdfArea = 1.0f / area_;
  return ps;
}

std::shared_ptr<Object> makeCylinderShape(const Properties& props) {
  Vec3 p0 = props.getVector("p0", Vec3(0, 0, 0)), p1 = props.getVector("p1", Vec3(0, 0, 1));
  float radius = props.getFloat("radius", 1.0f);
  if (!(radius > 0.0f)) throw props.error("radius", "the radius must be positive");
  float len = length(p1 - p0);
  if (!(len > 0.0f)) throw props.error("p1", "p0 and p1 must differ: they are the ends of the cylinder's axis");
  Frame frame = Frame::fromNormal((p1 - p0) / len);
  Matrix4 axes = Matrix4::identity();
  for (int row = 0; row < 3; ++row) {
    axes.m[row][0] = frame.s[row];
    axes.m[row][1] = frame.t[row];
    axes.m[row][2] = frame.n[row];
  }
  Transform toWorld = props.getTransform("to_world") * Transform::translate(p0) * Transform(axes, axes.transpose()) *
                      Transform::scale(Vec3(radius, radius, len));
  auto shape = std::make_shared<CylinderShape>(toWorld, props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  if (shape->emitter && !shape->keepsRound())
    throw props.error("to_world",
                      "an emitting cylinder needs a to_world that keeps it round (no shear, the same "
                      "scale across its axis): its area and area sampling assume so");
  return shape;
}

}  // namespace columba
