#include "sensors/bsdf_visualizer_sensor.h"

namespace columba {

std::optional<Ray> BSDFVisualizerSensor::generateRay(Vec2 filmPosition) const {
  float x = 2.0f * filmPosition.x / float(film().width()) - 1.0f;
  float y = 1.0f - 2.0f * filmPosition.y / float(film().height());
  float r = std::sqrt(x * x + y * y);
  if (r >= 1.0f) return std::nullopt;
  // theta = r pi/2 and phi = atan2(y, x), whose cosine and sine are x / r and y / r.
  float sinTheta, cosTheta;
  sinCosWithinQuarterTurn(r * kHalfPi, sinTheta, cosTheta);
  float scale = r > 0.0f ? sinTheta / r : 0.0f;
  Vec3 d(x * scale, y * scale, cosTheta);
  Ray ray;
  ray.o = d * distance_;
  ray.d = -d;
  return ray;
}

std::shared_ptr<Object> makeBSDFVisualizerSensor(const Properties& props) {
  float distance = props.getFloat("distance", 0.1f);
  if (!(distance > 0.0f)) throw props.error("distance", "distance must be positive");
  return std::make_shared<BSDFVisualizerSensor>(sensorFilm(props), sensorSampler(props), distance);
}

}  // namespace columba
