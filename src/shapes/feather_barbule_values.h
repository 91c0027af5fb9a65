#pragma once
// What the per-vertex barbule values of a feather PLY mean: the convention of the paper's own
// implementation, whose files must render the same in Columba (docs/feather-ply.md).
//
// - H (spacing): the file stores it in a legacy unit; the model's spacing is 2.5 times it.
// - mu (tilt): the file stores the model's tilt with the opposite sign.
// - height (cortex thickness, um): as given.
// - A file without the values gets the feather's own defaults (file H 0.5, mu 0.35,
//   height 0.65), not the BSDF's parameters.
// - A model tilt or height of exactly 0 stands for "the BSDF's own parameter" (the original
//   treats a zero as unset); the reader rejects a spacing of 0.
// - Near the ramus the barbules tilt further: within an angular distance d_r of the barb's centre
//   line, 0.1 of the strip's half-angle, the model tilt gains 0.5 (d / d_r - 1) radians.
namespace columba {

inline constexpr float kFileSpacingUnit = 2.5f;  // model H per file H

inline constexpr float kDefaultFileSpacing = 0.5f;
inline constexpr float kDefaultFileTilt = 0.35f;         // radians
inline constexpr float kDefaultCortexThickness = 0.65f;  // um

constexpr float modelSpacingFromFile(float fileH) { return kFileSpacingUnit * fileH; }
constexpr float fileSpacingFromModel(float modelH) { return modelH / kFileSpacingUnit; }
constexpr float modelTiltFromFile(float fileMu) { return -fileMu; }
constexpr float fileTiltFromModel(float modelMu) { return -modelMu; }

// The ramus zone, as a fraction of the strip's half-angle, and the extra tilt at the centre line.
inline constexpr float kRamusTiltZone = 0.1f;
inline constexpr float kRamusTiltAtCentre = 0.5f;  // radians

// Extra model tilt of barbules at angular distance `angle` (radians, either side) from the barb's
// centre line on a strip of half-angle `edgeAngle`: -0.5 at the centre line, rising linearly to 0
// at the edge of the ramus zone, 0 beyond it.
inline float ramusTilt(float angle, float edgeAngle) {
  const float zone = kRamusTiltZone * edgeAngle;
  const float d = angle < 0.0f ? -angle : angle;
  return d < zone ? kRamusTiltAtCentre * (d / zone - 1.0f) : 0.0f;
}

}  // namespace columba
