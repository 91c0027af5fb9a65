#pragma once
// The field of view of Mitsuba's projective cameras and projector: `fov` in degrees along
// `fov_axis` (x by default), or, as Mitsuba does without `fov`, that of a lens of `focal_length`
// (50mm by default) on 36 x 24 mm film, measured on the diagonal and fitted to the image's aspect.
#include <string>
#include "core/properties.h"
#include "core/vector.h"

namespace columba {

struct FieldOfView {
  float degrees = 0.0f;
  std::string axis;  // x, y, diagonal, smaller or larger
};

// fov and fov_axis, or focal_length, checked (InputError naming the line and value).
FieldOfView readFieldOfView(const Properties& props);

// The half extents of the image plane at unit distance, tan of half the angle along x and along y,
// for an image `aspect` = width / height.
Vec2 tanHalfAngles(const FieldOfView& fov, float aspect);

// Where the point `planePoint` of the plane z = 1 lies on the image, as (u, v) in [0, 1]^2 across
// and down it, for half extents `tanHalf`: Mitsuba's camera-to-sample mapping, the image's left on
// the camera's +x side and its top on +y.
inline Vec2 imageUV(Vec2 planePoint, Vec2 tanHalf) {
  return Vec2((1.0f - planePoint.x / tanHalf.x) * 0.5f, (1.0f - planePoint.y / tanHalf.y) * 0.5f);
}

inline constexpr float kDefaultFocalLengthMm = 50.0f;
// Diagonal field of view, degrees, of a lens of `focalLengthMm` on 36 x 24 mm film.
float diagonalFovOfFocalLength(float focalLengthMm);

}  // namespace columba
