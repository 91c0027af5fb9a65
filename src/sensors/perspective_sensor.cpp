#include "sensors/perspective_sensor.h"

#include <cmath>

namespace columba {

PerspectiveSensor::PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                     const PerspectiveParameters& view)
    : Sensor(std::move(film), std::move(sampler)), toWorld_(view.toWorld), clip_(view.clip) {
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

PerspectiveParameters readPerspectiveParameters(const Properties& props) {
  return {props.getTransform("to_world"), readFieldOfView(props), sensorClipRange(props)};
}

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props) {
  const PerspectiveParameters view = readPerspectiveParameters(props);
  // Mitsuba reads the focal plane's distance for every projective camera; a pinhole has none.
  if (props.has("focus_distance")) props.getFloat("focus_distance");
  return std::make_shared<PerspectiveSensor>(sensorFilm(props), sensorSampler(props), view);
}

}  // namespace columba
