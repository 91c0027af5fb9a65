#include "sensors/perspective_sensor.h"

#include <cmath>
#include <cstdlib>

namespace columba {

PerspectiveSensor::PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                     const Transform& toWorld, float fovDegrees, const std::string& fovAxis,
                                     float nearClip, float farClip)
    : Sensor(std::move(film), std::move(sampler)), toWorld_(toWorld), nearClip_(nearClip), farClip_(farClip) {
  float aspect = float(this->film().width()) / float(this->film().height());
  float t = std::tan(0.5f * degToRad(fovDegrees));
  std::string axis = fovAxis;
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

std::optional<Ray> PerspectiveSensor::generateRay(Vec2 filmPosition) const {
  float nx = 2.0f * filmPosition.x / float(film().width()) - 1.0f;
  float ny = 2.0f * filmPosition.y / float(film().height()) - 1.0f;
  // Image right is camera -x (x points left); image down is camera -y.
  Vec3 local = normalize(Vec3(-nx * tanHalfX_, -ny * tanHalfY_, 1.0f));
  Ray ray;
  ray.o = toWorld_.point(Vec3(0, 0, 0));
  ray.d = normalize(toWorld_.vector(local));
  ray.tmin = nearClip_ / local.z;
  ray.tmax = farClip_ / local.z;
  return ray;
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

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props) {
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
  float nearClip = props.getFloat("near_clip", 0.01f), farClip = props.getFloat("far_clip", 10000.0f);
  if (!(nearClip >= 0.0f && farClip > nearClip)) throw props.error("far_clip", "need 0 <= near_clip < far_clip");
  return std::make_shared<PerspectiveSensor>(sensorFilm(props), sensorSampler(props), props.getTransform("to_world"),
                                             fov, axis, nearClip, farClip);
}

}  // namespace columba
