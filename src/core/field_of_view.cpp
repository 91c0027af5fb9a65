/*! parameters fov
| parameter | type | default | meaning | Mitsuba 3 |
| fov | float | — | the field of view in degrees, in (0, 180), along `fov_axis`; not together with `focal_length` | same |
| fov_axis | string | `x` | the axis `fov` spans: `x`, `y`, `diagonal`, `smaller` or `larger` | same |
| focal_length | float or string | `50mm` | the focal length of a lens over a 36 × 24 mm film, a number or a string `<x>mm` or `<x>`, when `fov` is not given: the diagonal field of view | same |
*/
#include "core/field_of_view.h"

#include <cmath>
#include <cstdlib>

#include "core/math.h"

namespace columba {

float diagonalFovOfFocalLength(float focalLengthMm) {
  // The diagonal of a 36 x 24 mm film seen from the lens.
  return radToDeg(2.0f * std::atan(std::sqrt(36.0f * 36.0f + 24.0f * 24.0f) / (2.0f * focalLengthMm)));
}

namespace {

// `focal_length` as Mitsuba reads it: "<x>mm" or "<x>" as a string, or a number, in mm.
float focalLengthMm(const Properties& props) {
  if (!props.isString("focal_length")) return props.getFloat("focal_length", kDefaultFocalLengthMm);
  std::string text = props.getString("focal_length");
  if (text.size() > 2 && text.compare(text.size() - 2, 2, "mm") == 0) text.erase(text.size() - 2);
  char* end = nullptr;
  const float value = std::strtof(text.c_str(), &end);
  if (text.empty() || *end != '\0')
    throw props.error("focal_length", "cannot read focal_length '" + props.getString("focal_length") +
                                          "' (write it as <x>mm, e.g. 50mm)");
  return value;
}

}  // namespace

FieldOfView readFieldOfView(const Properties& props) {
  if (props.has("fov") && props.has("focal_length"))
    throw props.error("focal_length", "give either fov or focal_length, not both");
  FieldOfView fov;
  if (props.has("fov")) {
    fov.degrees = props.getFloat("fov");
    if (!(fov.degrees > 0.0f && fov.degrees < 180.0f))
      throw props.error("fov", "fov must be in (0, 180) degrees, not " + std::to_string(fov.degrees));
    fov.axis = props.getString("fov_axis", "x");
    if (fov.axis != "x" && fov.axis != "y" && fov.axis != "diagonal" && fov.axis != "smaller" && fov.axis != "larger")
      throw props.error("fov_axis", "fov_axis must be x, y, diagonal, smaller or larger, not '" + fov.axis + "'");
  } else {
    const float focalLength = focalLengthMm(props);
    if (!(focalLength > 0.0f && std::isfinite(focalLength)))
      throw props.error("focal_length", "focal_length must be positive, not " + std::to_string(focalLength));
    fov.degrees = diagonalFovOfFocalLength(focalLength);
    fov.axis = "diagonal";
  }
  return fov;
}

Vec2 tanHalfAngles(const FieldOfView& fov, float aspect) {
  const float t = std::tan(0.5f * degToRad(fov.degrees));
  std::string axis = fov.axis;
  if (axis == "smaller") axis = aspect > 1.0f ? "y" : "x";
  if (axis == "larger") axis = aspect > 1.0f ? "x" : "y";
  if (axis == "x") return Vec2(t, t / aspect);
  if (axis == "y") return Vec2(t * aspect, t);
  const float d = std::sqrt(aspect * aspect + 1.0f);  // diagonal
  return Vec2(t * aspect / d, t / d);
}

}  // namespace columba
