#pragma once
// Affine transforms as 4x4 matrices (row-major, column vectors), kept with their inverse.
#include <array>
#include "core/vector.h"

namespace columba {

struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};
  static Matrix4 identity();
  Matrix4 operator*(const Matrix4& o) const;
  // Throws std::runtime_error for a singular matrix.
  Matrix4 inverse() const;
  Matrix4 transpose() const;
};

class Transform {
 public:
  Transform() : Transform(Matrix4::identity(), Matrix4::identity()) {}
  explicit Transform(const Matrix4& m) : Transform(m, m.inverse()) {}
  Transform(const Matrix4& m, const Matrix4& inv)
      : m_(m), inv_(inv), affine_(m.m[3][0] == 0.0 && m.m[3][1] == 0.0 && m.m[3][2] == 0.0 && m.m[3][3] == 1.0) {}

  static Transform translate(const Vec3& d);
  static Transform scale(const Vec3& s);
  // Rotation by `angleDeg` degrees about `axis` (right-handed), built as Mitsuba builds it: the
  // axis is used as given, so for an axis that is not unit length the matrix also scales and
  // shears. Its inverse is exact (Mitsuba keeps the transpose instead).
  static Transform rotate(const Vec3& axis, float angleDeg);
  // Camera-to-world: camera looks along +z toward `target`, with +y near `up` (Mitsuba's convention).
  static Transform lookAt(const Vec3& origin, const Vec3& target, const Vec3& up);

  // `a * b` applies b first, then a.
  Transform operator*(const Transform& o) const { return Transform(m_ * o.m_, o.inv_ * inv_); }
  Transform inverse() const { return Transform(inv_, m_); }

  Vec3 point(const Vec3& p) const;
  Vec3 vector(const Vec3& v) const;
  Vec3 normal(const Vec3& n) const;  // uses the inverse transpose; not normalised
  const Matrix4& matrix() const { return m_; }
  const Matrix4& inverseMatrix() const { return inv_; }
  bool isIdentity() const;
  // Whether the linear part is orthonormal to `tolerance`: a rotation, possibly with a mirror,
  // which keeps lengths, angles and solid angles.
  bool isRigid(float tolerance = 1e-4f) const;

 private:
  Matrix4 m_, inv_;
  bool affine_;  // bottom row (0, 0, 0, 1): points need no homogeneous division
};

}  // namespace columba
