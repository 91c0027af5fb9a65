#include "sensors/perspective_sensor.h"

#include <cmath>
#include <cstdlib>

namespace columba {

PerspectiveSensor::PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                     const PerspectiveParameters& view)
    : Sensor(std::move(film), std::move(sampler)), toWorld_(view.toWorld), clip_(view.clip) {
  toWorldVolume_ = std::abs(
      dot(toWorld_.vector(Vec3(1, 0, 0)), cross(toWorld_.vector(Vec3(0, 1, 0)), toWorld_.vector(Vec3(0, 0, 1)))));
  float aspect = float(this->film().width()) / float(this->film().height());
  float t = std::tan(0.5f * degToRad(view.fovDegrees));
  std::string axis = view.fovAxis;
  if (axis == "smaller") axis = aspect > 1.0f ? "y" : "x";
  if (axis == "larger") axis = aspect > 1.0f ? "x" : "y";
  if (axis == "x") {
    tanHalfX_ = t;
    tanHalfY_ = t / aspect;
  } else if (axis == "y") {
    tanHalfY_ = t;
    tanHalfX_ = t * aspect;
  } else {  // diagonal
    float d = std::sqrt(aspect * aspect + 1.0f);
    tanHalfX_ = t * aspect / d;
    tanHalfY_ = t / d;
  }
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
  const Vec2 filmPosition((1.0f - q.x / tanHalfX_) * 0.5f * float(film().width()),
                          (1.0f - q.y / tanHalfY_) * 0.5f * float(film().height()));
  if (!filmReaches(filmPosition)) return std::nullopt;
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

float diagonalFovOfFocalLength(float focalLengthMm) {
  // The diagonal of a 36 x 24 mm film seen from the lens.
  return radToDeg(2.0f * std::atan(std::sqrt(36.0f * 36.0f + 24.0f * 24.0f) / (2.0f * focalLengthMm)));
}

namespace {

// `focal_length` as Mitsuba reads it: "<x>mm" or "<x>" as a string, or a number, in mm.
float focalLengthMm(const Properties& props) {
  if (!props.isString("focal_length")) return props.getFloat("focal_length", kDefaultFocalLengthMm);
  std::string text = props.getString("focal_length");
  if (text.size() > 2 && text.compare(text.size() - 2, 2, "mm") == 0) text.erase(text.size() - 2);
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (text.empty() || *end != '\0')
    throw props.error("focal_length", "cannot read focal_length '" + props.getString("focal_length") +
                                          "' (write it as <x>mm, e.g. 50mm)");
  return value;
}

}  // namespace

PerspectiveParameters readPerspectiveParameters(const Properties& props) {
  if (props.has("fov") && props.has("focal_length"))
    throw props.error("focal_length", "give either fov or focal_length, not both");
  float fov;
  std::string axis;
  if (props.has("fov")) {
    fov = props.getFloat("fov");
    if (!(fov > 0.0f && fov < 180.0f))
      throw props.error("fov", "fov must be in (0, 180) degrees, not " + std::to_string(fov));
    axis = props.getString("fov_axis", "x");
    if (axis != "x" && axis != "y" && axis != "diagonal" && axis != "smaller" && axis != "larger")
      throw props.error("fov_axis", "fov_axis must be x, y, diagonal, smaller or larger, not '" + axis + "'");
  } else {
    // Mitsuba's default lens: a focal length (50 mm unless given) on 36 x 24 mm film, on the diagonal.
    const float focalLength = focalLengthMm(props);
    if (!(focalLength > 0.0f && std::isfinite(focalLength)))
      throw props.error("focal_length", "focal_length must be positive, not " + std::to_string(focalLength));
    fov = diagonalFovOfFocalLength(focalLength);
    axis = "diagonal";
  }
  return {props.getTransform("to_world"), fov, axis, sensorClipRange(props)};
}

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props) {
  const PerspectiveParameters view = readPerspectiveParameters(props);
  // Mitsuba reads the focal plane's distance for every projective camera; a pinhole has none.
  if (props.has("focus_distance")) props.getFloat("focus_distance");
  return std::make_shared<PerspectiveSensor>(sensorFilm(props), sensorSampler(props), view);
}

}  // namespace columba
