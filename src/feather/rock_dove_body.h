#pragma once
// The body of a procedural rock dove (Columba livia) under its feathers: a union of ellipsoids
// for the torso, breast, neck, head, folded wings and tail, and simple shapes for the beak and
// eyes, in centimetres (x toward the beak, y up, z toward the bird's left). Its proportions and
// the measurements they come from are in docs/rock-dove.md.
#include <string>
#include <vector>

#include "core/vector.h"

namespace columba {

// An ellipsoid: the unit sphere scaled by `radii` along the axes of a frame rotated by `pitch`
// radians about z (raising +x toward +y), then moved to `centre`.
struct Ellipsoid {
  Vec3 centre, radii;
  float pitch = 0.0f;

  // (x - c)^T A (x - c) - 1 for the ellipsoid's quadric A: negative inside, 0 on the surface.
  float implicit(const Vec3& p) const;
  // The outward unit normal at (or near) a point of the surface.
  Vec3 normal(const Vec3& p) const;
  // The surface point at spherical angles (theta from +y of the ellipsoid's frame, phi about it).
  Vec3 point(float theta, float phi) const;
};

// What covers a part of the body.
enum class Plumage {
  Iridescent,  // neck feathers: barbule BSDF, green above, purple below
  Grey,        // head, breast, body, wings and tail: grey contour feathers
  None,        // the beak and eyes
};

struct BodyPart {
  std::string name;
  Ellipsoid shape;
  Plumage plumage;
};

class RockDoveBody {
 public:
  RockDoveBody();

  const std::vector<BodyPart>& parts() const { return parts_; }
  // The smallest implicit value over the feathered parts: negative inside the body.
  float inside(const Vec3& p) const;
  // Whether `p`, on part `index`'s surface, lies on the body's surface (inside no other feathered part).
  bool onSurface(const Vec3& p, size_t index) const;
  // The direction feathers point at `p` on part `index` (tangent to it): down the neck toward the
  // breast, and from head to tail elsewhere.
  Vec3 featherDirection(const Vec3& p, size_t index) const;
  // Whether a feather may not reach `p`: within an eye or the beak. With `ring`, also on the bare
  // skin around them, the eye rings and the cere at the beak's base, as on a real rock dove.
  bool face(const Vec3& p, bool ring) const;
  // Fraction along the neck from its base (0, at the breast) to the head (1) of a point near it.
  float neckFraction(const Vec3& p) const;

  // Where the neck runs: from the breast to the back of the head.
  static constexpr float kNeckBaseX = 4.2f, kNeckBaseY = 5.0f, kNeckTopX = 7.3f, kNeckTopY = 10.9f;

 private:
  std::vector<BodyPart> parts_;
};

}  // namespace columba
