#pragma once
// `thinlens`: the perspective camera with a thin lens of `aperture_radius` at its centre, focused
// on the plane z = `focus_distance` in camera space (Mitsuba's model): every ray of a film point
// passes through the point of the focal plane that the pinhole camera's ray would reach, from a
// point of the lens's disk chosen by the aperture sample.
#include "sensors/perspective_sensor.h"

namespace columba {

class ThinLensSensor : public PerspectiveSensor {
 public:
  ThinLensSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, const PerspectiveParameters& view,
                 float apertureRadius, float focusDistance);
  using Sensor::generateRay;
  std::optional<Ray> generateRay(Vec2 filmPosition, Vec2 apertureSample) const override;
  bool needsApertureSample() const override { return true; }

 protected:
  Vec3 lensPoint(Vec2 u) const override;
  float focusDistance() const override { return focusDistance_; }

 private:
  float apertureRadius_, focusDistance_;
};

std::shared_ptr<Object> makeThinLensSensor(const Properties& props);

}  // namespace columba
