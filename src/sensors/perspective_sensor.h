#pragma once
// `perspective`: a pinhole camera looking along its local +z, with +y up and +x to the left
// (Mitsuba's camera frame, so `lookat` transforms place it the same way). Its field of view is
// Mitsuba's (core/field_of_view.h): `fov` along `fov_axis`, or that of a lens of `focal_length`.
#include "core/field_of_view.h"
#include "core/properties.h"
#include "core/transform.h"
#include "sensors/sensor.h"

namespace columba {

// What the perspective and thin-lens cameras share: where they are, their field of view and their
// clip range.
struct PerspectiveParameters {
  Transform toWorld;
  FieldOfView fov;
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

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props);

}  // namespace columba
