#pragma once
// Orthonormal frame (s, t, n); local z is the normal, as in Mitsuba and pbrt.
#include "core/vector.h"

namespace columba {

struct Frame {
  Vec3 s{1, 0, 0}, t{0, 1, 0}, n{0, 0, 1};
  Frame() = default;
  Frame(const Vec3& s_, const Vec3& t_, const Vec3& n_) : s(s_), t(t_), n(n_) {}
  // Any frame around `n` (Duff et al. 2017, branchless).
  static Frame fromNormal(const Vec3& n) {
    float sign = std::copysign(1.0f, n.z);
    float a = -1.0f / (sign + n.z);
    float b = n.x * n.y * a;
    return Frame(Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), Vec3(b, sign + n.y * n.y * a, -n.y), n);
  }
  // Frame with normal `n` whose first axis s (local x) is as close as possible to `sDirection`:
  // shapes pass dp/du, so a BSDF's local x follows the surface's u direction as in Mitsuba.
  static Frame fromNormalAndS(const Vec3& n, const Vec3& sDirection) {
    Vec3 s = sDirection - dot(sDirection, n) * n;
    if (lengthSquared(s) < 1e-12f) return fromNormal(n);
    s = normalize(s);
    return Frame(s, cross(n, s), n);
  }
  Vec3 toLocal(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace columba
