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
  // Importance as Mitsuba's perspective camera's, W = 1 / (A cos^3 theta) per unit solid angle
  // (A: the image plane's area at unit distance, theta: the angle to the optical axis), so that
  // light tracing gives each pixel the mean radiance of its camera samples.
  bool hasImportance() const override { return true; }
  bool hasImportanceFromDirections() const override { return true; }
  std::optional<ImportanceSample> sampleImportance(const Vec3& ref, Vec2 u) const override;
  std::optional<ImportanceSample> sampleImportanceFrom(const Vec3& direction, Vec2 u) const override;
  // Half extents of the image plane at unit distance: tan of half the field of view.
  float tanHalfFovX() const { return tanHalfX_; }
  float tanHalfFovY() const { return tanHalfY_; }

 protected:
  // The camera-space point of the image plane z = 1 that `filmPosition` sees.
  Vec3 imagePlanePoint(Vec2 filmPosition) const;
  const Transform& toWorld() const { return toWorld_; }
  const ClipRange& clip() const { return clip_; }
  // The camera-space point of the lens that `u` picks, and the distance of the plane in focus:
  // for the pinhole, its centre and any distance.
  virtual Vec3 lensPoint(Vec2 /*u*/) const { return Vec3(0, 0, 0); }
  virtual float focusDistance() const { return 1.0f; }

 private:
  // The connection through the lens point `lens` along the camera-space direction `local` (any
  // length, toward the reference), `worldDistance` away (0: at infinity).
  std::optional<ImportanceSample> importanceAlong(const Vec3& lens, const Vec3& local, float worldDistance) const;

  Transform toWorld_;
  float tanHalfX_, tanHalfY_;  // image-plane half extents at unit distance
  float toWorldVolume_;        // |det| of to_world's linear part: how it changes solid angles
  ClipRange clip_;
};

std::shared_ptr<Object> makePerspectiveSensor(const Properties& props);

}  // namespace columba
