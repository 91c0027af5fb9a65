#pragma once
// `perspective`: a pinhole camera looking along its local +z, with +y up and +x to the left
// (Mitsuba's camera frame, so `lookat` transforms place it the same way).
#include "core/transform.h"
#include "scene/properties.h"
#include "sensors/sensor.h"

namespace columba {

class PerspectiveSensor : public Sensor {
 public:
  PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, const Transform& toWorld,
                    float fovDegrees, const std::string& fovAxis, float nearClip, float farClip);
  std::optional<Ray> generateRay(Vec2 filmPosition) const override;

 private:
  Transform toWorld_;
  float tanHalfX_, tanHalfY_;  // image-plane half extents at unit distance
  float nearClip_, farClip_;
};

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props);

}  // namespace columba
