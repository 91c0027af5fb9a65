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

// What the perspective and thin-lens cameras share: where they are, their field of view (degrees,
// along fovAxis) and their clip range.
struct PerspectiveParameters {
  Transform toWorld;
  float fovDegrees;
  std::string fovAxis;
  ClipRange clip;
};
// fov and fov_axis or focal_length, near_clip, far_clip and to_world, checked.
PerspectiveParameters readPerspectiveParameters(const Properties& props);

class PerspectiveSensor : public Sensor {
 public:
  PerspectiveSensor(std::shared_ptr<Film> film, std::shared_ptr<Sampler> sampler, const PerspectiveParameters& view);
  using Sensor::generateRay;
  std::optional<Ray> generateRay(Vec2 filmPosition, Vec2 apertureSample) const override;
  // Half extents of the image plane at unit distance: tan of half the field of view.
  float tanHalfFovX() const { return tanHalfX_; }
  float tanHalfFovY() const { return tanHalfY_; }

 protected:
  // The camera-space point of the image plane z = 1 that `filmPosition` sees.
  Vec3 imagePlanePoint(Vec2 filmPosition) const;
  const Transform& toWorld() const { return toWorld_; }
  const ClipRange& clip() const { return clip_; }

 private:
  Transform toWorld_;
  float tanHalfX_, tanHalfY_;  // image-plane half extents at unit distance
  ClipRange clip_;
};

inline constexpr float kDefaultFocalLengthMm = 50.0f;
// Diagonal field of view, degrees, of a lens of `focalLengthMm` on 36 x 24 mm film.
float diagonalFovOfFocalLength(float focalLengthMm);

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props);

}  // namespace columba
