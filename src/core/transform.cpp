#include "core/transform.h"

#include <cmath>
#include <stdexcept>

namespace columba {

Matrix4 Matrix4::identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0;
  return r;
}

Matrix4 Matrix4::operator*(const Matrix4& o) const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

Matrix4 Matrix4::transpose() const {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
  return r;
}

// Gauss-Jordan elimination with partial pivoting.
Matrix4 Matrix4::inverse() const {
  Matrix4 a = *this, inv = identity();
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a.m[r][c]) > std::abs(a.m[pivot][c])) pivot = r;
    if (std::abs(a.m[pivot][c]) < 1e-300) throw std::runtime_error("singular transform matrix");
    std::swap(a.m[c], a.m[pivot]);
    std::swap(inv.m[c], inv.m[pivot]);
    double d = 1.0 / a.m[c][c];
    for (int j = 0; j < 4; ++j) {
      a.m[c][j] *= d;
      inv.m[c][j] *= d;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      double f = a.m[r][c];
      for (int j = 0; j < 4; ++j) {
        a.m[r][j] -= f * a.m[c][j];
        inv.m[r][j] -= f * inv.m[c][j];
      }
    }
  }
  return inv;
}

Transform Transform::translate(const Vec3& d) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][3] = d[i];
    inv.m[i][3] = -d[i];
  }
  return Transform(m, inv);
}

Transform Transform::scale(const Vec3& s) {
  Matrix4 m = Matrix4::identity(), inv = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    if (s[i] == 0.0f) throw std::runtime_error("scale by zero");
    m.m[i][i] = s[i];
    inv.m[i][i] = 1.0 / s[i];
  }
  return Transform(m, inv);
}

Transform Transform::rotate(const Vec3& axis, float angleDeg) {
  // Rodrigues' formula with the axis as given, as Mitsuba builds it: an axis that is not unit length
  // also scales and shears (scenes written for Mitsuba, the paper's simulation1 light among them,
  // are drawn with that matrix).
  double x = axis.x, y = axis.y, z = axis.z;
  double a = double(angleDeg) * kPiDouble / 180.0;
  double s = std::sin(a), c = std::cos(a), t = 1.0 - c;
  Matrix4 m = Matrix4::identity();
  m.m[0][0] = t * x * x + c;
  m.m[0][1] = t * x * y - s * z;
  m.m[0][2] = t * x * z + s * y;
  m.m[1][0] = t * x * y + s * z;
  m.m[1][1] = t * y * y + c;
  m.m[1][2] = t * y * z - s * x;
  m.m[2][0] = t * x * z - s * y;
  m.m[2][1] = t * y * z + s * x;
  m.m[2][2] = t * z * z + c;
  // Mitsuba keeps the transpose as the inverse whatever the axis, so that ray hits (through the
  // inverse) and area samples (through the matrix) see two different surfaces. The transpose is
  // kept only where it is the inverse to double precision; elsewhere the inverse is computed.
  const Matrix4 transposed = m.transpose();
  const Matrix4 product = m * transposed;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(product.m[i][j] - (i == j ? 1.0 : 0.0)) > 1e-12) return Transform(m);
  return Transform(m, transposed);
}

Transform Transform::lookAt(const Vec3& origin, const Vec3& target, const Vec3& up) {
  Vec3 dir = target - origin;
  if (lengthSquared(dir) == 0.0f) throw std::runtime_error("lookat: origin equals target");
  dir = normalize(dir);
  Vec3 left = cross(up, dir);
  if (lengthSquared(left) < 1e-12f) throw std::runtime_error("lookat: up is parallel to the view direction");
  left = normalize(left);
  Vec3 newUp = cross(dir, left);
  Matrix4 m = Matrix4::identity();
  for (int i = 0; i < 3; ++i) {
    m.m[i][0] = left[i];
    m.m[i][1] = newUp[i];
    m.m[i][2] = dir[i];
    m.m[i][3] = origin[i];
  }
  return Transform(m);
}

Vec3 Transform::point(const Vec3& p) const {
  // Shapes and sensors are placed by affine maps, and points are transformed per ray.
  if (affine_)
    return Vec3(float(m_.m[0][0] * p.x + m_.m[0][1] * p.y + m_.m[0][2] * p.z + m_.m[0][3]),
                float(m_.m[1][0] * p.x + m_.m[1][1] * p.y + m_.m[1][2] * p.z + m_.m[1][3]),
                float(m_.m[2][0] * p.x + m_.m[2][1] * p.y + m_.m[2][2] * p.z + m_.m[2][3]));
  double r[4];
  for (int i = 0; i < 4; ++i) r[i] = m_.m[i][0] * p.x + m_.m[i][1] * p.y + m_.m[i][2] * p.z + m_.m[i][3];
  double w = r[3] == 1.0 ? 1.0 : 1.0 / r[3];
  return Vec3(float(r[0] * w), float(r[1] * w), float(r[2] * w));
}

Vec3 Transform::vector(const Vec3& v) const {
  return Vec3(float(m_.m[0][0] * v.x + m_.m[0][1] * v.y + m_.m[0][2] * v.z),
              float(m_.m[1][0] * v.x + m_.m[1][1] * v.y + m_.m[1][2] * v.z),
              float(m_.m[2][0] * v.x + m_.m[2][1] * v.y + m_.m[2][2] * v.z));
}

Vec3 Transform::normal(const Vec3& n) const {
  return Vec3(float(inv_.m[0][0] * n.x + inv_.m[1][0] * n.y + inv_.m[2][0] * n.z),
              float(inv_.m[0][1] * n.x + inv_.m[1][1] * n.y + inv_.m[2][1] * n.z),
              float(inv_.m[0][2] * n.x + inv_.m[1][2] * n.y + inv_.m[2][2] * n.z));
}

bool Transform::isRigid(float tolerance) const {
  const Vec3 x = vector(Vec3(1, 0, 0)), y = vector(Vec3(0, 1, 0)), z = vector(Vec3(0, 0, 1));
  return std::abs(length(x) - 1.0f) <= tolerance && std::abs(length(y) - 1.0f) <= tolerance &&
         std::abs(length(z) - 1.0f) <= tolerance && std::abs(dot(x, y)) <= tolerance &&
         std::abs(dot(y, z)) <= tolerance && std::abs(dot(x, z)) <= tolerance;
}

bool Transform::isIdentity() const {
  Matrix4 id = Matrix4::identity();
  return m_.m == id.m;
}

}  // namespace columba
