#pragma once
// `bsdfvisualizer`: an imaging scatterometer. The image disk maps to the hemisphere above the
// origin: for film position (p_x, p_y) of a W x H film, u = 2 p_x / W - 1 and v = 2 p_y / H - 1
// (v grows downward with the image row, as in the paper's implementation: what a camera at the
// sample looking up at the instrument's dome sees), theta = r pi/2 with r = |(u, v)|,
// phi = atan2(v, u). Every pixel looks at the origin from its direction; outside the disk, black.
#include "core/properties.h"
#include "sensors/sensor.h"

namespace columba {

class BSDFVisualizerSensor : public Sensor {
 public:
  BSDFVisualizerSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, float distance)
      : Sensor(std::move(film), std::move(sampler)),
        distance_(distance),
        xScale_(2.0f / float(this->film().width())),
        yScale_(2.0f / float(this->film().height())) {}
  using Sensor::generateRay;
  std::optional<Ray> generateRay(Vec2 filmPosition, Vec2 apertureSample) const override;
  bool seesAnyOf(Vec2 lo, Vec2 hi) const override;

 private:
  float distance_;         // how far from the origin rays start (below the scene's lights)
  float xScale_, yScale_;  // film pixels to the image disk's [-1, 1]
};

std::shared_ptr<Object> makeBSDFVisualizerSensor(const Properties& props);

}  // namespace columba
