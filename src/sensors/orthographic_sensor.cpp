/*! plugin sensor orthographic
Parallel rays along the camera's local +z from the plane z = `near_clip`, over [-1, 1] in x and [-1/aspect, 1/aspect] in y (x to the left, y up); `to_world` places and sizes that rectangle. Rays reach `far_clip` − `near_clip`. Its nested `film` and `sampler` are as `perspective`'s.
Mitsuba 3: as Mitsuba 3's `orthographic`; `focus_distance` is read and has no effect.
uses: clip
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | places and sizes the camera's rectangle | same |
| focus_distance | float | — | accepted; no effect | same |
*/
#include "sensors/orthographic_sensor.h"

#include <cmath>

namespace columba {

OrthographicSensor::OrthographicSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                                       const Transform& toWorld, const ClipRange& clip)
    : Sensor(std::move(film), std::move(sampler)),
      toWorld_(toWorld),
      direction_(normalize(toWorld.vector(Vec3(0, 0, 1)))),
      clip_(clip) {
  const float aspect = float(this->film().width()) / float(this->film().height());
  const Vec3 across = cross(toWorld.vector(Vec3(2.0f, 0, 0)), toWorld.vector(Vec3(0, 2.0f / aspect, 0)));
  inverseProjectedArea_ = 1.0f / std::abs(dot(across, direction_));
}

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

std::optional<ImportanceSample> OrthographicSensor::sampleImportance(const Vec3& ref, Vec2) const {
  const Vec3 p = toWorld_.inverse().point(ref);
  const float aspect = float(film().width()) / float(film().height());
  const Vec2 filmPosition((1.0f - p.x) * 0.5f * float(film().width()),
                          (1.0f - p.y * aspect) * 0.5f * float(film().height()));
  if (!onFilm(filmPosition)) return std::nullopt;
  const Vec3 start = toWorld_.point(Vec3(p.x, p.y, clip_.nearClip));
  const float t = dot(ref - start, direction_);
  if (!(t > 0.0f && t < clip_.farClip - clip_.nearClip)) return std::nullopt;
  ImportanceSample s;
  s.origin = start;
  s.rayStart = start;
  s.filmPosition = filmPosition;
  s.weight = inverseProjectedArea_;
  return s;
}

std::shared_ptr<Object> makeOrthographicSensor(const Properties& props) {
  // Mitsuba reads the focal plane's distance for every projective camera; this one has none.
  if (props.has("focus_distance")) props.getFloat("focus_distance");
  auto sensor = std::make_shared<OrthographicSensor>(sensorFilm(props), sensorSampler(props),
                                                     props.getTransform("to_world"), sensorClipRange(props));
  sensor->readMedium(props);
  return sensor;
}

}  // namespace columba
