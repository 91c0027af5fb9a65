#pragma once
// The `feather` shape: barbs read from a feather PLY (see feather_ply.h), each segment a
// cylindrical strip (see barb_strip.h), intersected exactly as Embree user geometry with one
// primitive per segment (primID = barb * kBarbSegments + segment).
//
// Conventions:
// - to_world is applied to the vertices and normals at load. Widths (barbwidth, ramuswidth and
//   the strip radius) are in PLY units and scale with the cube root of |det| of to_world.
// - The strip radius is R = (barbwidth / 2) / sin(cover), so at a barb's base the strip spans
//   +-cover around its normal. Barbs taper from full width at the base (first vertex) to
//   kTipWidthFraction of it at the tip, quadratically in the position along the barb (so
//   vanes stay closed and fray toward their edges); the radius stays R, the angular span
//   shrinks. Within a segment the width is interpolated linearly.
// - Strip normals: the per-vertex vane normals, projected perpendicular to each segment, are
//   fitted (least squares) by one normal per barb transported from segment to segment by
//   reflection in the mitre planes. That transport is what lets consecutive cylinders meet
//   exactly at their mitre; it cannot follow a twist of the vane normal about the barb axis.
// - Hits: HitRecord.u = position along the segment (0 at its start vertex, 1 at its end),
//   HitRecord.v = sin(phi), phi the angle from the strip normal toward b = cross(barb direction,
//   normal).
//   SurfaceInteraction.uv = (position along the whole barb in [0, 1], phi / cover).
// - Shading frame: n = the cylinder's outward normal at the hit (ng), t = the barbule
//   direction, at angle `span` from the barb axis toward the tip and away from the ramus
//   (mirrored on the two sides), s = cross(t, n). On the ramus, |phi| < asin(ramuswidth/2/R),
//   there are no barbules: t is the barb axis (onRamus() tells those hits apart).
// - Shading frame orientation: right-handed (s, t, n) with s pointing toward the ramus on both
//   sides, as in the original implementation, so that one tilt mu describes two rows of barbules
//   that are mirror images; on the positive side (phi > 0) t therefore points back along the
//   barbule, toward the ramus (the barbule BSDF is symmetric under t -> -t).
// - Serrated edges: beyond 0.94 of the strip's local half-angle phi_edge the strip is a row of
//   sawteeth (barb_serration.h). The gaps are dropped in the Embree callbacks, so rays pass
//   through them (the original ends the path there instead).
// - Barbule values (feather_barbule_values.h), the original implementation's convention: per
//   vertex, the model's H is 2.5 x the file's H, the model's mu is -(file mu), height is as
//   given; they are interpolated linearly along the segment (the original holds the value of
//   the segment's base-ward vertex). A file without them gets the feather's defaults (file H
//   0.5, mu 0.35, height 0.65 um), not the BSDF's. At a hit at angle phi, mu gains the ramus
//   tilt 0.5 (|phi| / d_r - 1) where |phi| < d_r = 0.1 phi_edge. The hit carries them as its
//   attributes "H", "mu" and "height" (what a mesh_attribute texture reads as vertex_H, vertex_mu
//   and vertex_height); the barbule BSDF reads a mu or height of exactly 0 as its own parameter,
//   as the original does.
#include <array>
#include <memory>
#include <vector>
#include "core/properties.h"
#include "core/shape_point_values.h"
#include "core/transform.h"
#include "io/feather_ply.h"
#include "shapes/barb_strip.h"
#include "shapes/feather_barbule_values.h"
#include "shapes/shape.h"

namespace columba {

struct FeatherShapeParams {
  float barbWidth = 0.015f;
  float ramusWidth = 0.00063f;
  float cover = 0.78f;  // radians
  float span = 0.45f;   // radians
  Transform toWorld;
};

class FeatherShape : public Shape {
 public:
  static constexpr float kTipWidthFraction = 0.3f;
  // Mean barb width over its length, relative to the base (the taper's average).
  static constexpr float kMeanWidthFraction = 1.0f - (1.0f - kTipWidthFraction) / 3.0f;

  // Throws InputError for invalid parameters or barbs (zero-length segments, sharp turns).
  FeatherShape(FeatherPlyData ply, const FeatherShapeParams& params);

  unsigned addToEmbree(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, const HitRecord& hit) const override;
  size_t primitiveCount() const override { return barbCount_ * kBarbSegments; }

  bool onRamus(const SurfaceInteraction& si) const { return std::abs(si.uv.y * cover_) < ramusHalfAngle_; }
  size_t barbCount() const { return barbCount_; }
  // The strip of Embree primitive `primID`, in world space.
  BarbStrip strip(size_t primID) const;
  // Nearest hit of the ray o + t d, t in (tmin, tmax), with the strip of primitive `primID`.
  bool intersectStrip(size_t primID, const Vec3& o, const Vec3& d, float tmin, float tmax, StripHit& hit) const {
    return strips_[primID].intersect(profiles_[primID % kBarbSegments], o, d, tmin, tmax, hit);
  }
  // A box containing the strip of primitive `primID`.
  void stripBounds(size_t primID, Vec3& lo, Vec3& hi) const {
    strips_[primID].bounds(profiles_[primID % kBarbSegments], lo, hi);
  }
  float radius() const { return radius_; }
  // What the feather gives its BSDF at its points, for BSDF::noteValuesGivenByShape; `name` names
  // the feather in messages. Given at every point, so that a BSDF's own constants for them have
  // no effect on it: H always, mu and height unless some segment has 0 at both ends (a zero leaves
  // the BSDF's own, as in the original). The layer stack, where the file gives one.
  ShapePointValues givenValues(const std::string& name) const;
  // Bytes held by the loaded geometry (not counting Embree's BVH).
  size_t memoryBytes() const;

 private:
  size_t barbCount_ = 0;
  // kBarbSegments per barb, world space, base first. Ray queries read nothing else, and the
  // vertices are not kept: strip() recovers the mitre planes from the neighbours' axes.
  std::vector<PackedStrip> strips_;
  std::array<StripProfile, kBarbSegments> profiles_;  // by segment index: all barbs taper alike
  // A vertex's barbule values (H, mu, height) in the model's terms, before the ramus tilt.
  struct BarbuleValues {
    float h, mu, height;
  };
  static constexpr BarbuleValues kDefaultBarbuleValues{modelSpacingFromFile(kDefaultFileSpacing),
                                                       modelTiltFromFile(kDefaultFileTilt), kDefaultCortexThickness};
  std::vector<BarbuleValues> barbuleValues_;  // per vertex, or empty when the file has none
  ShapePointValues given_;                    // all but the name givenValues() gives it
  // Per vertex, the barbule BSDF's layer stack (the file's `stack`), or empty when it has none.
  std::vector<uint8_t> layerStacks_;
  float radius_ = 0.0f, ramusHalfAngle_ = 0.0f;
  float cover_ = 0.0f, cosSpan_ = 1.0f, sinSpan_ = 0.0f;
};

// <shape type="feather">: its parameters are in docs/reference/shapes.md.
std::shared_ptr<Object> makeFeatherShape(const Properties& props);

}  // namespace columba
