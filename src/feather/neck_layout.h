#pragma once
// Where the feathers of a generated neck go. The neck is a section of a cylinder whose axis runs
// along +y (from the head toward the body), seen from +z; positions on it are given by
// surface coordinates (X, Y): X the arc length across the neck, Y the height along it. The
// section covers x in about [-2.4, 3.4], y in [-1.6, 3.0] and bulges toward +z: the view of
// the reference neck scene, whose camera 6.1 PLY units above (it scales the PLY by 0.1) sees
// x in [-1.7, 2.7] and y in [-0.95, 2.35] with Mitsuba's default 39.6 degree field of view.
//
// Feathers sit in rows across the neck, pointing down it (+y), like roof tiles: each row covers
// the bases of the next, odd columns are offset by half a row, and every feather rises from its
// base at a small pitch, so that a feather lies above all feathers of later rows wherever they
// overlap. Cortex thickness, and so colour, varies smoothly over the neck: green on the upper
// neck, purple below a wavy boundary.
#include <cstdint>
#include <vector>
#include "core/vector.h"

namespace columba {

class NeckSurface {
 public:
  static constexpr float kRadius = 4.0f;  // of the cylinder
  static constexpr float kCentreX = 0.5f;
  static constexpr float kHalfWidth = 3.2f;  // arc length from the centre line to either side
  static constexpr float kTop = -1.6f, kBottom = 3.0f;

  Vec3 point(float X, float Y) const;
  Vec3 normal(float X, float Y) const;
};

struct FeatherPlacement {
  Vec2 base;          // surface coordinates of the rachis base
  float heading = 0;  // angle of the rachis from +Y toward +X, radians
  float scale = 1;    // of the feather design's size
  float pitch = 0;    // rise per unit length along the rachis
  uint64_t seed = 0;  // for the feather's own randomness
};

struct NeckLayout {
  std::vector<FeatherPlacement> feathers;  // in stacking order: earlier ones lie on top
  float rowSpacing = 0, columnSpacing = 0;
  float featherLength = 0, featherWidth = 0;  // before each feather's own scale
};

NeckLayout layOutNeck(int featherCount, uint64_t seed);

// Fraction of purple (against green) barbules at surface point (X, Y), smooth over the neck: 0
// above a wavy boundary around height `boundary` (Y), 1 below it, blending over `blend` on either
// side of it (0: a sharp edge).
class NeckColouring {
 public:
  static constexpr float kDefaultBoundary = 0.7f, kDefaultBlend = 0.35f;
  explicit NeckColouring(uint64_t seed, float boundary = kDefaultBoundary, float blend = kDefaultBlend);
  float purple(float X, float Y) const;

 private:
  float phase1_, phase2_, boundary_, blend_;
};

}  // namespace columba
