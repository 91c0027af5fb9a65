#pragma once
// The planform of one feather in its own 2D frame: x runs along the rachis from the base
// (x = 0) to the tip (x = length), y across it. Barbs leave the rachis on both sides at an angle
// that closes from base to tip, curl toward the tip as they go, and end on the vane's outline,
// a rounded blade widest a little below the middle.
#include <array>
#include <cstdint>
#include "core/vector.h"
#include "io/feather_ply.h"

namespace columba {

struct FeatherDesign {
  float length = 1.2f;
  float width = 0.8f;  // widest extent of the vane, both sides together
  int barbsPerSide = 50;
  float bareBase = 0.08f;           // fraction of the rachis below the first barb (the calamus)
  float barbAngleBase = 0.96f;      // angle between barb and rachis at the base, radians (55 degrees)
  float barbAngleTip = 0.52f;       // ... and at the tip (30 degrees)
  float barbCurl = 0.35f;           // how much a barb turns toward the tip from its base to its end
  float rachisBend = 0.04f;         // sideways offset of the rachis tip, as a fraction of the length
  float rachisHalfWidth = 0.0075f;  // barbs start this far from the rachis centre line
};

// Half-width of the vane at fraction t of the rachis.
float vaneHalfWidth(const FeatherDesign& design, float t);

// Rachis centre line and its unit direction at fraction t.
Vec2 rachisPoint(const FeatherDesign& design, float t);
Vec2 rachisDirection(const FeatherDesign& design, float t);

// Barb `index` (0 = nearest the base) on side +1 or -1, its length scaled by `lengthScale` and
// its angle offset by `angleOffset` radians (the caller's per-barb randomness).
std::array<Vec2, kBarbVertices> barbPolyline(const FeatherDesign& design, int side, int index, float lengthScale,
                                             float angleOffset);

// The rachis centre line from base to tip.
std::array<Vec2, kBarbVertices> rachisPolyline(const FeatherDesign& design);

// Barbs per side for neighbouring barbs to lie edge to edge, when they are `barbWidth` wide at
// the base and `meanWidthFraction` of that on average along their length.
int barbsToTile(const FeatherDesign& design, float barbWidth, float meanWidthFraction);

// Distance between neighbouring barbs, measured across them, at the middle of the vane.
float barbSpacing(const FeatherDesign& design);

}  // namespace columba
