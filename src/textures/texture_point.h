#pragma once
// Where a texture is looked up: the surface's (u, v), and on a mesh whose file carries per-vertex
// or per-face values, the triangle hit and the hit's barycentric coordinates there (what Mitsuba's
// mesh_attribute texture reads); on a shape that gives BSDF parameters per point (a feather's
// barbule values), those values there.
#include <cstdint>
#include "core/surface_attributes.h"
#include "core/vector.h"

namespace columba {

class MeshAttributes;

struct TexturePoint {
  TexturePoint() = default;
  TexturePoint(Vec2 uv) : uv(uv) {}  // NOLINT: most lookups need only (u, v)
  TexturePoint(Vec2 uv, const SurfaceAttributes* attributes) : uv(uv), attributes(attributes) {}

  Vec2 uv;
  const MeshAttributes* mesh = nullptr;  // null off meshes and on meshes without attributes
  uint32_t triangle = 0;
  Vec2 barycentric;                               // the weights of the triangle's second and third vertex
  const SurfaceAttributes* attributes = nullptr;  // null where the shape gives none
};

}  // namespace columba
