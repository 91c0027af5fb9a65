#pragma once
// `orthographic`: parallel rays along the camera's local +z from the plane z = near_clip, over
// [-1, 1] in x and [-1/aspect, 1/aspect] in y (x to the left and y up, as the perspective camera),
// as Mitsuba 3 defines it; to_world places and sizes that plane. Rays reach far_clip - near_clip.
#include "core/properties.h"
#include "core/transform.h"
#include "sensors/sensor.h"

namespace columba {

class OrthographicSensor : public Sensor {
 public:
  OrthographicSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, const Transform& toWorld,
                     const ClipRange& clip);
  using Sensor::generateRay;
  std::optional<Ray> generateRay(Vec2 filmPosition, Vec2 apertureSample) const override;
  // Importance spread evenly over the sensor's rectangle along its one direction: a point is
  // seen from the point of the rectangle behind it, with weight 1 / (the rectangle's area across
  // the direction). Light from infinity reaches it along one direction only, which no light
  // tracing finds.
  bool hasImportance() const override { return true; }
  std::optional<ImportanceSample> sampleImportance(const Vec3& ref, Vec2 u) const override;

 private:
  Transform toWorld_;
  Vec3 direction_;  // world space
  ClipRange clip_;
  float inverseProjectedArea_;  // 1 / the area of the sensor's rectangle across direction_
};

std::shared_ptr<Object> makeOrthographicSensor(const Properties& props);

}  // namespace columba
