#pragma once
// The ragged edges of a barb strip, cut as the paper's own implementation cuts them: the inner
// 94 % of the strip's half-angle is whole; beyond it the strip is a row of sawteeth, three per
// segment, each at full width at its tip-ward end and narrowing linearly to 94 % toward the base.
// A point at angle |phi| in that band, at fraction f in [0, 1) of its tooth counted from the
// tooth's tip-ward end, belongs to the strip when phi_edge - |phi| >= 0.06 phi_edge f.
#include <cmath>

namespace columba {

struct BarbSerration {
  static constexpr float kWholeFraction = 0.94f;  // of the strip's half-angle
  static constexpr float kTeethPerSegment = 3.0f;

  // Whether the strip keeps the point with |sin(phi)| = `absSinAngle` on a cross-section whose
  // edge is at sin(phi_edge) = `sinEdge`, at `axial` (0 at the segment's base-ward vertex, 1 at
  // its tip-ward one). Points inside the whole part cost one comparison: sin is concave on
  // [0, pi/2], so |sin phi| <= 0.94 sin phi_edge implies |phi| <= 0.94 phi_edge.
  static bool keeps(float absSinAngle, float sinEdge, float axial) {
    if (absSinAngle <= kWholeFraction * sinEdge) return true;
    const float angle = std::asin(std::fmin(absSinAngle, 1.0f)), edge = std::asin(std::fmin(sinEdge, 1.0f));
    if (angle <= kWholeFraction * edge) return true;
    // Distance from the tooth's tip-ward end; beyond the segment's tip-ward cut (axial > 1, within
    // the mitre slack) fmod is negative and the point is kept, as in the original.
    const float tooth = std::fmod(kTeethPerSegment * (1.0f - axial), 1.0f);
    return tooth * ((1.0f - kWholeFraction) * edge) <= edge - angle;
  }
};

}  // namespace columba
