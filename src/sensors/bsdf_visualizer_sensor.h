#pragma once
// `bsdfvisualizer`: an imaging scatterometer. The image disk maps to the hemisphere above the
// origin (theta = r * pi/2, phi = atan2(y, x), image up = +y); every pixel looks at the origin
// from its direction. Pixels outside the disk are black.
#include "scene/properties.h"
#include "sensors/sensor.h"

namespace columba {

class BSDFVisualizerSensor : public Sensor {
 public:
  BSDFVisualizerSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, float distance)
      : Sensor(std::move(film), std::move(sampler)),
        distance_(distance),
        xScale_(2.0f / float(this->film().width())),
        yScale_(2.0f / float(this->film().height())) {}
  std::optional<Ray> generateRay(Vec2 filmPosition) const override;
  bool seesAnyOf(Vec2 lo, Vec2 hi) const override;

 private:
  float distance_;  // how far from the origin rays start (below the scene's lights)
  float xScale_, yScale_;  // film pixels to the image disk's [-1, 1]
};

std::shared_ptr<Object> makeBSDFVisualizerSensor(const Properties& props);

}  // namespace columba
