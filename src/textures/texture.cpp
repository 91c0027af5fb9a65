#include "textures/texture.h"

#include <stdexcept>

namespace columba {

Vec3 Texture::evalTriple(const TexturePoint&) const {
  throw std::logic_error("evalTriple: this texture holds no raw triples (check givesTriples first)");
}

Vec2 applyToUV(const Transform& toUV, Vec2 uv) {
  const Matrix4& m = toUV.matrix();
  return Vec2(float(m.m[0][0] * uv.x + m.m[0][1] * uv.y + m.m[0][3]),
              float(m.m[1][0] * uv.x + m.m[1][1] * uv.y + m.m[1][3]));
}

}  // namespace columba
