#include "sensors/orthographic_sensor.h"

#include <cmath>

namespace columba {

OrthographicSensor::OrthographicSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                       const Transform& toWorld, const ClipRange& clip)
    : Sensor(std::move(film), std::move(sampler)),
      toWorld_(toWorld),
      direction_(normalize(toWorld.vector(Vec3(0, 0, 1)))),
      clip_(clip) {}

std::optional<Ray> OrthographicSensor::generateRay(Vec2 filmPosition, Vec2 /*apertureSample*/) const {
  const float x = filmPosition.x / float(film().width()), y = filmPosition.y / float(film().height());
  const float aspect = float(film().width()) / float(film().height());
  Ray ray;
  ray.o = toWorld_.point(Vec3(1.0f - 2.0f * x, (1.0f - 2.0f * y) / aspect, clip_.nearClip));
  ray.d = direction_;
  ray.tmin = 0.0f;
  ray.tmax = clip_.farClip - clip_.nearClip;
  return ray;
}

std::shared_ptr<Object> makeOrthographicSensor(const Properties& props) {
  // Mitsuba reads the focal plane's distance for every projective camera; this one has none.
  if (props.has("focus_distance")) props.getFloat("focus_distance");
  return std::make_shared<OrthographicSensor>(sensorFilm(props), sensorSampler(props), props.getTransform("to_world"),
                                              sensorClipRange(props));
}

}  // namespace columba
