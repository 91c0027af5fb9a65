#include "shapes/vertex_normals.h"

#include <cmath>

namespace columba {

namespace {

// The angle between two edges leaving a corner; atan2 keeps it accurate near 0 and pi.
float cornerAngle(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

}  // namespace

std::vector<Vec3> angleWeightedVertexNormals(const std::vector<Vec3>& positions, const std::vector<uint32_t>& indices) {
  std::vector<Vec3> normals(positions.size(), Vec3(0, 0, 0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t* idx = &indices[t];
    const Vec3 p[3] = {positions[idx[0]], positions[idx[1]], positions[idx[2]]};
    const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
    const float len = length(n);
    if (!(len > 0.0f && std::isfinite(len))) continue;
    for (int k = 0; k < 3; ++k) {
      const float angle = cornerAngle(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
      normals[idx[k]] += n * (angle / len);
    }
  }
  for (Vec3& n : normals) {
    const float len = length(n);
    n = len > 0.0f ? n / len : Vec3(0, 0, 0);
  }
  return normals;
}

}  // namespace columba
