/*! plugin sensor perspective
A pinhole camera looking along its local +z, x to the left and y up. It holds a nested `film` (default: `hdrfilm`) and `sampler` (default: `independent`).
Mitsuba 3: the same parameters and defaults; `focus_distance` is read, as Mitsuba reads it for every projective camera, and has no effect.
uses: fov, clip
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | the camera's frame (a `lookat`, for example) | same |
| focus_distance | float | — | accepted; a pinhole has no focal plane | same |
*/
#include "sensors/perspective_sensor.h"

#include <cmath>

namespace columba {

PerspectiveSensor::PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                     const PerspectiveParameters& view)
    : Sensor(std::move(film), std::move(sampler)), toWorld_(view.toWorld), clip_(view.clip) {
  toWorldVolume_ = std::abs(
      dot(toWorld_.vector(Vec3(1, 0, 0)), cross(toWorld_.vector(Vec3(0, 1, 0)), toWorld_.vector(Vec3(0, 0, 1)))));
  const Vec2 tanHalf = tanHalfAngles(view.fov, float(this->film().width()) / float(this->film().height()));
  tanHalfX_ = tanHalf.x;
  tanHalfY_ = tanHalf.y;
}

Vec3 PerspectiveSensor::imagePlanePoint(Vec2 filmPosition) const {
  float nx = 2.0f * filmPosition.x / float(film().width()) - 1.0f;
  float ny = 2.0f * filmPosition.y / float(film().height()) - 1.0f;
  // Image right is camera -x (x points left); image down is camera -y.
  return Vec3(-nx * tanHalfX_, -ny * tanHalfY_, 1.0f);
}

std::optional<Ray> PerspectiveSensor::generateRay(Vec2 filmPosition, Vec2 /*apertureSample*/) const {
  Vec3 local = normalize(imagePlanePoint(filmPosition));
  Ray ray;
  ray.o = toWorld_.point(Vec3(0, 0, 0));
  ray.d = normalize(toWorld_.vector(local));
  ray.tmin = clip_.nearClip / local.z;
  ray.tmax = clip_.farClip / local.z;
  return ray;
}

std::optional<ImportanceSample> PerspectiveSensor::importanceAlong(const Vec3& lens, const Vec3& local,
                                                                   float worldDistance) const {
  if (!(local.z > 0.0f)) return std::nullopt;
  // The point of the plane z = 1 whose camera ray through `lens` goes along `local`: the ray
  // passes through the point of the plane in focus that this image-plane point is the image of.
  const Vec3 q = lens / focusDistance() + local / local.z;
  const Vec2 uv = imageUV(Vec2(q.x, q.y), Vec2(tanHalfX_, tanHalfY_));
  const Vec2 filmPosition(uv.x * float(film().width()), uv.y * float(film().height()));
  if (!onFilm(filmPosition)) return std::nullopt;
  // Solid angles: the image plane's area dA = d(omega) / cos^3 theta in camera space, and the
  // world's solid angle is the camera's times |det M| / |M w|^3 (w unit, M to_world's linear part).
  const float cosTheta = local.z / length(local);
  const float stretch = length(toWorld_.vector(local / length(local)));
  const float toWorldSolidAngle = toWorldVolume_ / (stretch * stretch * stretch);
  const float imagePlaneArea = 4.0f * tanHalfX_ * tanHalfY_;
  ImportanceSample s;
  s.origin = toWorld_.point(lens);
  s.rayStart = toWorld_.point(lens + local * (clip_.nearClip / local.z));
  s.filmPosition = filmPosition;
  s.weight = 1.0f / (imagePlaneArea * cosTheta * cosTheta * cosTheta * toWorldSolidAngle);
  if (worldDistance > 0.0f) s.weight /= worldDistance * worldDistance;
  return s;
}

std::optional<ImportanceSample> PerspectiveSensor::sampleImportance(const Vec3& ref, Vec2 u) const {
  const Vec3 p = toWorld_.inverse().point(ref);
  if (!(p.z > clip_.nearClip && p.z < clip_.farClip)) return std::nullopt;
  const Vec3 lens = lensPoint(u);
  return importanceAlong(lens, p - lens, length(ref - toWorld_.point(lens)));
}

std::optional<ImportanceSample> PerspectiveSensor::sampleImportanceFrom(const Vec3& direction, Vec2 u) const {
  return importanceAlong(lensPoint(u), toWorld_.inverse().vector(direction), 0.0f);
}

PerspectiveParameters readPerspectiveParameters(const Properties& props) {
  return {props.getTransform("to_world"), readFieldOfView(props), sensorClipRange(props)};
}

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props) {
  const PerspectiveParameters view = readPerspectiveParameters(props);
  // Mitsuba reads the focal plane's distance for every projective camera; a pinhole has none.
  if (props.has("focus_distance")) props.getFloat("focus_distance");
  auto sensor = std::make_shared<PerspectiveSensor>(sensorFilm(props), sensorSampler(props), view);
  sensor->readMedium(props);
  return sensor;
}

}  // namespace columba
