/*! plugin shape instance
A placed copy of one `shapegroup` (a `<ref>` to it, or nested), its `to_world` applied on top of the group's shapes' own. Instances use Embree's instancing, so a group instanced many times is stored once.
Mitsuba 3: as Mitsuba 3's `instance`; a transform that Embree's single-precision instancing cannot trace is refused.
| parameter | type | default | meaning | Mitsuba 3 |
| H | float | the shapes' own | the barbule spacing this copy's barbule BSDFs use everywhere on it, in place of its shapes' per-point values; positive | not in Mitsuba 3 |
| mu | float | the shapes' own | the barbule tilt (radians) this copy gives in the same way | not in Mitsuba 3 |
| height | float | the shapes' own | the cortex thickness (µm, at least 0) this copy gives in the same way: copies of one feather in different colours | not in Mitsuba 3 |
| to_world | transform | identity | an affine transform (last row 0, 0, 0, 1); refused when degenerate: a 3×3 determinant beyond float range, or a shrink that takes world points within 10⁶ of the origin beyond 1.8 × 10¹⁸ in the group's space (as a uniform scale below about 5 × 10⁻¹³ does) | same |
*/
#include "shapes/instance_shape.h"

#include "barbule/parameters.h"

#include <fmt/format.h>

#include <cfloat>
#include <cmath>
#include <optional>

namespace columba {

namespace {

// Embree traces a group through an instance in single precision: it inverts the float matrix (its
// 3x3 part by the adjugate over the determinant) and aborts the process on a ray whose
// coordinates in the group's space exceed FLT_LARGE.
constexpr double kEmbreeLargest = 1.844e18;  // Embree's FLT_LARGE
// The world coordinates (in magnitude) up to which an instance's rays must stay within that range.
constexpr double kWorldReach = 1e6;

// Why Embree cannot trace through `toWorld`, if it cannot.
std::optional<std::string> embreeInstanceProblem(const Matrix4& toWorld) {
  double a[3][3], translation = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) a[r][c] = double(float(toWorld.m[r][c]));
    translation = std::max(translation, std::abs(double(float(toWorld.m[r][3]))));
  }
  // The adjugate: cofactors, transposed.
  double adj[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
      adj[r][c] = a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1];
    }
  const double det = a[0][0] * adj[0][0] + a[0][1] * adj[1][0] + a[0][2] * adj[2][0];
  double largestMinor = 0.0;
  for (const auto& row : adj)
    for (double v : row) largestMinor = std::max(largestMinor, std::abs(v));
  if (!(std::abs(det) >= FLT_MIN && std::abs(det) <= FLT_MAX && largestMinor <= FLT_MAX))
    return fmt::format(
        "its 3x3 part has determinant {:g}, which Embree's single-precision inverse cannot take "
        "(it needs {:g} to {:g} in magnitude)",
        det, FLT_MIN, FLT_MAX);
  // How far a world point within kWorldReach of the origin can lie from the group's origin.
  double magnification = 0.0;
  for (const auto& row : adj)
    magnification = std::max(magnification, (std::abs(row[0]) + std::abs(row[1]) + std::abs(row[2])) / std::abs(det));
  const double reach = magnification * (kWorldReach + translation);
  if (reach > kEmbreeLargest)
    return fmt::format(
        "it shrinks the group so much that world points within {:g} of the origin would lie up to "
        "{:g} away in the group's space, beyond the {:g} Embree can trace",
        kWorldReach, reach, kEmbreeLargest);
  return std::nullopt;
}

// A barbule value for the whole copy, if given: finite and at least `lowest` (above it when `strictly`).
std::optional<float> barbuleValue(const Properties& props, const char* name, float lowest, bool strictly) {
  if (!props.has(name)) return std::nullopt;
  const float v = props.getFloat(name);
  if (!std::isfinite(v) || v < lowest || (strictly && v == lowest))
    throw props.error(
        name, fmt::format("must be a finite number {} {:g}, not {:g}", strictly ? "above" : "of at least", lowest, v));
  return v;
}

}  // namespace

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
  si.attributes.overrideWith(values_);
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
  if (std::optional<std::string> problem = embreeInstanceProblem(toWorld.matrix()))
    throw props.error("to_world", "the transform is degenerate: " + *problem);
  SurfaceAttributes values;
  auto give = [&](SurfaceAttributeKey key, std::optional<float> value) {
    if (value) values.set(key, *value);
  };
  give(kBarbuleSpacingAttribute, barbuleValue(props, "H", 0.0f, true));
  give(kBarbuleTiltAttribute, barbuleValue(props, "mu", -INFINITY, false));
  give(kCortexThicknessAttribute, barbuleValue(props, "height", 0.0f, false));
  return std::make_shared<InstanceShape>(groups.front(), toWorld, values);
}

}  // namespace columba
