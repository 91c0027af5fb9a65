/*! plugin sensor bsdfvisualizer
An imaging scatterometer: the image disk maps to the hemisphere above the origin. For film position (p_x, p_y) of a W × H film, u = 2 p_x / W − 1 and v = 2 p_y / H − 1 (v grows downward with the image row: what a camera at the sample looking up at the instrument's dome sees), θ = r π/2 with r = |(u, v)| and φ = atan2(v, u). Every pixel looks at the origin from its direction; outside the disk the image is black. Its nested `film` and `sampler` are as `perspective`'s.
Mitsuba 3: not in Mitsuba 3.
| parameter | type | default | meaning | Mitsuba 3 |
| distance | float | 0.1 | how far from the origin the rays start; positive | not in Mitsuba 3 |
*/
#include "sensors/bsdf_visualizer_sensor.h"

#include "core/fast_math.h"

namespace columba {

std::optional<Ray> BSDFVisualizerSensor::generateRay(Vec2 filmPosition, Vec2 /*apertureSample*/) const {
  // Film rows grow downward and so does v: the top half of the image looks from -y.
  float x = filmPosition.x * xScale_ - 1.0f;
  float y = filmPosition.y * yScale_ - 1.0f;
  float rSqr = x * x + y * y;
  if (rSqr >= 1.0f) return std::nullopt;
  // theta = r pi/2 and phi = atan2(y, x), whose cosine and sine are x / r and y / r:
  // sin(theta) / r = (pi/2) sin(theta) / theta.
  float sinOverTheta, cosTheta;
  sincAndCosWithinQuarterTurn(std::sqrt(rSqr) * kHalfPi, sinOverTheta, cosTheta);
  float scale = kHalfPi * sinOverTheta;
  Vec3 d(x * scale, y * scale, cosTheta);
  Ray ray;
  ray.o = d * distance_;
  ray.d = -d;
  return ray;
}

bool BSDFVisualizerSensor::seesAnyOf(Vec2 lo, Vec2 hi) const {
  // The point of the rectangle nearest the disk's centre, in the disk's coordinates.
  float x0 = lo.x * xScale_ - 1.0f, x1 = hi.x * xScale_ - 1.0f;
  float y0 = lo.y * yScale_ - 1.0f, y1 = hi.y * yScale_ - 1.0f;
  float x = clampf(0.0f, x0, x1), y = clampf(0.0f, y0, y1);
  return x * x + y * y < 1.0f;
}

std::shared_ptr<Object> makeBSDFVisualizerSensor(const Properties& props) {
  float distance = props.getFloat("distance", 0.1f);
  if (!(distance > 0.0f)) throw props.error("distance", "distance must be positive");
  auto sensor = std::make_shared<BSDFVisualizerSensor>(sensorFilm(props), sensorSampler(props), distance);
  sensor->readMedium(props);
  return sensor;
}

}  // namespace columba
