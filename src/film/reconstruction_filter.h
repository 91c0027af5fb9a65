#pragma once
// Pixel reconstruction filters (Mitsuba's `rfilter`). As in Mitsuba, a filter is separable: the
// weight of a film position for a pixel is eval(dx) eval(dy), with (dx, dy) its offset from the
// pixel's centre. Every camera sample adds its value to each pixel the filter reaches from it,
// with that weight (film/film_splats.h). Filters here are non-negative and normalised.
#include "core/object.h"

namespace columba {

// The widest filter: a sample may count for pixels at most this many pixels from its own, so
// radius - 1/2 must not exceed it.
inline constexpr int kMaxFilterReach = 16;
inline constexpr float kMaxFilterRadius = float(kMaxFilterReach) + 0.5f;
// The narrowest filter: every sample must reach its own pixel's centre, or a pixel would count
// few of its samples, or none (a filter narrower than this renders a mostly black image).
inline constexpr float kMinFilterRadius = 0.5f;

class ReconstructionFilter : public Object {
 public:
  // eval is 0 beyond this offset, in pixels.
  virtual float radius() const = 0;
  // The filter on one axis, normalised: it integrates to 1 over [-radius, radius].
  virtual float eval(float offset) const = 0;
};

}  // namespace columba
