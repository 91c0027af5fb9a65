/*! plugin sensor thinlens
A perspective camera with a thin lens: rays leave a disk of radius `aperture_radius` and meet on the plane z = `focus_distance` of its frame, which is sharp. Its nested `film` and `sampler` are as `perspective`'s.
Mitsuba 3: the same parameters; `focus_distance` defaults to `far_clip`; a `to_world` that scales is an error (distances on the lens and to the focal plane are the camera's).
uses: fov, clip
| parameter | type | default | meaning | Mitsuba 3 |
| to_world | transform | identity | the camera's frame; must not scale | — |
| aperture_radius | float | required | the lens radius; at least 0 | same |
| focus_distance | float | `far_clip` | the distance of the sharp plane; positive | — |
*/
#include "sensors/thin_lens_sensor.h"

#include <fmt/format.h>

#include <cmath>

#include "core/sampling.h"

namespace columba {

ThinLensSensor::ThinLensSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler,
                               const PerspectiveParameters& view, float apertureRadius, float focusDistance)
    : PerspectiveSensor(std::move(film), std::move(sampler), view),
      apertureRadius_(apertureRadius),
      focusDistance_(focusDistance) {}

Vec3 ThinLensSensor::lensPoint(Vec2 u) const {
  const Vec2 disk = sampleConcentricDisk(u);
  return Vec3(apertureRadius_ * disk.x, apertureRadius_ * disk.y, 0.0f);
}

std::optional<Ray> ThinLensSensor::generateRay(Vec2 filmPosition, Vec2 apertureSample) const {
  const Vec3 focus = imagePlanePoint(filmPosition) * focusDistance_;  // on the plane z = focusDistance_
  const Vec3 lens = lensPoint(apertureSample);
  const Vec3 local = normalize(focus - lens);
  Ray ray;
  ray.o = toWorld().point(lens);
  ray.d = normalize(toWorld().vector(local));
  ray.tmin = clip().nearClip / local.z;
  ray.tmax = clip().farClip / local.z;
  return ray;
}

std::shared_ptr<Object> makeThinLensSensor(const Properties& props) {
  const PerspectiveParameters view = readPerspectiveParameters(props);
  // Distances on the lens and to the focal plane are camera-space ones, so to_world must keep
  // lengths, as Mitsuba requires.
  const Matrix4& m = view.toWorld.matrix();
  for (int c = 0; c < 3; ++c) {
    const float length = std::sqrt(float(m.m[0][c] * m.m[0][c] + m.m[1][c] * m.m[1][c] + m.m[2][c] * m.m[2][c]));
    if (std::abs(length - 1.0f) > 1e-4f)
      throw props.error("to_world", fmt::format("the thinlens camera's to_world must not scale (its axis {} has length "
                                                "{:g}); size the scene instead",
                                                "xyz"[c], length));
  }
  const float apertureRadius = props.getFloat("aperture_radius");
  if (!(apertureRadius >= 0.0f && std::isfinite(apertureRadius)))
    throw props.error("aperture_radius", fmt::format("aperture_radius must be at least 0, not {:g}", apertureRadius));
  const float focusDistance = props.getFloat("focus_distance", view.clip.farClip);
  if (!(focusDistance > 0.0f && std::isfinite(focusDistance)))
    throw props.error("focus_distance", fmt::format("focus_distance must be positive, not {:g}", focusDistance));
  auto sensor =
      std::make_shared<ThinLensSensor>(sensorFilm(props), sensorSampler(props), view, apertureRadius, focusDistance);
  sensor->readMedium(props);
  return sensor;
}

}  // namespace columba
