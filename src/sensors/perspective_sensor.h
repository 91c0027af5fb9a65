#pragma once
// `perspective`: a pinhole camera looking along its local +z, with +y up and +x to the left
// (Mitsuba's camera frame, so `lookat` transforms place it the same way). Its field of view is
// `fov` (degrees, along `fov_axis`, x by default) or, as in Mitsuba, that of a lens of
// `focal_length` (50mm by default) on 36 x 24 mm film, measured on the diagonal and fitted to the
// image's aspect.
#include "core/properties.h"
#include "core/transform.h"
#include "sensors/sensor.h"

namespace columba {

class PerspectiveSensor : public Sensor {
 public:
  PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, const Transform& toWorld,
                    float fovDegrees, const std::string& fovAxis, float nearClip, float farClip);
  std::optional<Ray> generateRay(Vec2 filmPosition) const override;
  // Half extents of the image plane at unit distance: tan of half the field of view.
  float tanHalfFovX() const { return tanHalfX_; }
  float tanHalfFovY() const { return tanHalfY_; }

 private:
  Transform toWorld_;
  float tanHalfX_, tanHalfY_;  // image-plane half extents at unit distance
  float nearClip_, farClip_;
};

inline constexpr float kDefaultFocalLengthMm = 50.0f;
// Diagonal field of view, degrees, of a lens of `focalLengthMm` on 36 x 24 mm film.
float diagonalFovOfFocalLength(float focalLengthMm);

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props);

}  // namespace columba
