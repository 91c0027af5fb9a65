/*! plugin shape sphere
A sphere of `radius` around `center`, then `to_world`; a nested BSDF (default: `diffuse`) and optionally an `area` emitter, which needs a `to_world` that keeps the sphere round (its area and area sampling assume so).
Mitsuba 3: the same parameters and defaults.
uses: media
| parameter | type | default | meaning | Mitsuba 3 |
| center | point | (0, 0, 0) | the centre | same |
| radius | float | 1 | the radius; positive | same |
| to_world | transform | identity | applied after `center` and `radius` | same |
| flip_normals | boolean | false | normals point inward | same |
*/
#include "shapes/sphere_shape.h"

#include "core/sampling.h"
#include "shapes/triangle_mesh.h"

namespace columba {

SphereShape::SphereShape(const Transform& toWorld, bool flipNormals) : AnalyticShape(toWorld), flip_(flipNormals) {
  Vec3 ax = toWorld_.vector(Vec3(1, 0, 0)), ay = toWorld_.vector(Vec3(0, 1, 0)), az = toWorld_.vector(Vec3(0, 0, 1));
  radius_ = length(ax);
  round_ = std::abs(length(ay) - radius_) < 1e-5f * radius_ && std::abs(length(az) - radius_) < 1e-5f * radius_ &&
           std::abs(dot(ax, ay)) < 1e-5f * radius_ * radius_ && std::abs(dot(ax, az)) < 1e-5f * radius_ * radius_ &&
           std::abs(dot(ay, az)) < 1e-5f * radius_ * radius_;
  center_ = toWorldPoint(Vec3(0, 0, 0));
  area_ = 4.0f * kPi * radius_ * radius_;
}

std::optional<float> SphereShape::coneCosine(const Vec3& ref) const {
  float dist2 = lengthSquared(center_ - ref);
  if (!round_ || flip_ || dist2 <= radius_ * radius_ * 1.0001f) return std::nullopt;
  return safeSqrt(1.0f - radius_ * radius_ / dist2);
}

Vec2 SphereShape::uvOf(const Vec3& local) {
  // u = phi / (2 pi), v = theta / pi.
  const float phi = std::atan2(local.y, local.x);
  return Vec2((phi < 0 ? phi + kTwoPi : phi) * (0.5f * kInvPi), safeAcos(local.z) * kInvPi);
}

std::optional<ReferenceSample> SphereShape::sampleFrom(const Vec3& ref, Vec2 u, bool withTexturePoint) const {
  std::optional<float> cosMax = coneCosine(ref);
  if (!cosMax) return Shape::sampleFrom(ref, u, withTexturePoint);
  // Uniform over the cone of directions that see the sphere, then the nearest point along it.
  Vec3 axis = normalize(center_ - ref);
  Vec3 d = Frame::fromNormal(axis).toWorld(sampleUniformCone(u, *cosMax));
  Vec3 oc = ref - center_;
  float b = dot(oc, d), c = lengthSquared(oc) - radius_ * radius_;
  float t = -b - safeSqrt(b * b - c);  // grazing directions round to the tangent point
  ReferenceSample rs;
  rs.p = ref + d * t;
  rs.n = normalize(rs.p - center_);
  if (withTexturePoint) rs.point = uvOf(normalize(toLocalPoint(rs.p)));
  rs.pdf = uniformConePdf(*cosMax);
  return rs;
}

float SphereShape::pdfFrom(const Vec3& ref, const SurfaceInteraction& hit) const {
  std::optional<float> cosMax = coneCosine(ref);
  return cosMax ? uniformConePdf(*cosMax) : Shape::pdfFrom(ref, hit);
}

bool SphereShape::intersectWorld(const Vec3& worldO, const Vec3& worldD, float tmin, float tmax, float& t) const {
  Vec3 o = toLocalPoint(worldO), d = toLocalVector(worldD);
  // Solve |o + t d|^2 = 1 in double precision: grazing and distant rays stay accurate.
  double a = double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z;
  double b = 2.0 * (double(o.x) * d.x + double(o.y) * d.y + double(o.z) * d.z);
  double c = double(o.x) * o.x + double(o.y) * o.y + double(o.z) * o.z - 1.0;
  double t0, t1;
  if (!solveQuadratic(a, b, c, t0, t1)) return false;
  if (t0 > tmin && t0 < tmax) {
    t = float(t0);
    return true;
  }
  if (t1 > tmin && t1 < tmax) {
    t = float(t1);
    return true;
  }
  return false;
}

SurfaceInteraction SphereShape::interaction(const Ray& ray, const HitRecord& hit) const {
  SurfaceInteraction si;
  si.t = hit.t;
  si.shape = this;
  Vec3 local = normalize(toLocalPoint(ray.at(hit.t)));
  si.p = toWorldPoint(local);  // re-projected onto the surface
  si.ng = toWorldNormal(localNormal(local));
  si.uv = uvOf(local);
  si.dpdu = toWorld_.vector(Vec3(-local.y, local.x, 0) * kTwoPi);
  const float r = std::sqrt(local.x * local.x + local.y * local.y);
  if (r > 0.0f) si.dpdv = toWorld_.vector(Vec3(local.z * local.x / r, local.z * local.y / r, -r) * kPi);
  si.shading = Frame::fromNormalAndS(si.ng, toWorld_.vector(Vec3(-local.y, local.x, 0)));  // dp/du
  return si;
}

PositionSample SphereShape::samplePosition(Vec2 u, bool withTexturePoint) const {
  Vec3 local = sampleUniformSphere(u);
  PositionSample ps;
  ps.p = toWorldPoint(local);
  ps.n = toWorldNormal(localNormal(local));
  if (withTexturePoint) ps.point = uvOf(local);
  ps.pdfArea = 1.0f / area_;
  return ps;
}

std::shared_ptr<Object> makeSphereShape(const Properties& props) {
  Vec3 center = props.getVector("center", Vec3(0, 0, 0));
  float radius = props.getFloat("radius", 1.0f);
  if (!(radius > 0.0f)) throw props.error("radius", "the radius must be positive");
  Transform toWorld =
      props.getTransform("to_world") * Transform::translate(center) * Transform::scale(Vec3(radius, radius, radius));
  auto shape = std::make_shared<SphereShape>(toWorld, props.getBool("flip_normals", false));
  attachMaterial(props, *shape);
  if (shape->emitter && !shape->keepsRound())
    throw props.error("to_world",
                      "an emitting sphere needs a to_world that keeps it round (the same scale along every "
                      "axis, no shear): its area and area sampling assume so");
  return shape;
}

}  // namespace columba
