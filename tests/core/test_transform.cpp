#include <gtest/gtest.h>

#include <cmath>

#include "core/transform.h"

using namespace columba;

namespace {

void expectNear(const Vec3& a, const Vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

Transform general() {
  return Transform::translate(Vec3(0.3f, -2, 5)) * Transform::rotate(Vec3(0, 0, 1), 37) *
         Transform::rotate(Vec3(1, 0, 0), -21) * Transform::scale(Vec3(2, 0.5f, 3)) *
         Transform::lookAt(Vec3(1, 2, 3), Vec3(-1, 0, 0.5f), Vec3(0, 0, 1));
}

}  // namespace

TEST(Transform, ProductAppliesRightOperandFirst) {
  Transform t = Transform::translate(Vec3(1, 0, 0)) * Transform::scale(Vec3(2, 2, 2));
  expectNear(t.point(Vec3(1, 1, 1)), Vec3(3, 2, 2));
}

TEST(Transform, RotationIsRightHanded) {
  expectNear(Transform::rotate(Vec3(0, 0, 1), 90).vector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
  expectNear(Transform::rotate(Vec3(1, 0, 0), 90).vector(Vec3(0, 1, 0)), Vec3(0, 0, 1));
  expectNear(Transform::rotate(Vec3(0, 1, 0), 90).vector(Vec3(0, 0, 1)), Vec3(1, 0, 0));
}

TEST(Transform, RotationUsesItsAxisAsGivenAsMitsubaDoes) {
  // Mitsuba's rotate: R = cos(a) I + (1 - cos(a)) k k^T + sin(a) [k]x with the axis k as given.
  // For k = (1, 1, 0) and a = 23 degrees (the paper's
  // simulation1 light), with t = 1 - c: R = [[c + t, t, s], [t, c + t, -s], [-s, s, c]].
  const double a = 23.0 * M_PI / 180.0, c = std::cos(a), s = std::sin(a), t = 1.0 - c;
  Transform r = Transform::rotate(Vec3(1, 1, 0), 23.0f);
  // Column j of R is the image of the j-th unit vector.
  expectNear(r.vector(Vec3(1, 0, 0)), Vec3(float(t + c), float(t), float(-s)));
  expectNear(r.vector(Vec3(0, 1, 0)), Vec3(float(t), float(t + c), float(s)));
  expectNear(r.vector(Vec3(0, 0, 1)), Vec3(float(s), float(-s), float(c)));
  // Not a rotation: lengths change. Unlike Mitsuba's, the kept inverse is the inverse, not the
  // transpose, so that ray hits (through it) and area samples (through R) see one surface.
  EXPECT_GT(length(r.vector(Vec3(1, 0, 0))), 1.01f);
  const Matrix4 product = r.matrix() * r.inverseMatrix();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(product.m[i][j], i == j ? 1.0 : 0.0, 1e-12) << i << ", " << j;
  // A unit axis keeps the transpose, which is then the inverse.
  const Transform unit = Transform::rotate(Vec3(0, 0, 1), 23.0f);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(unit.inverseMatrix().m[i][j], unit.matrix().m[j][i]);
  // A unit axis gives the plain rotation.
  expectNear(Transform::rotate(Vec3(0.6f, 0.8f, 0), 90).vector(Vec3(0.6f, 0.8f, 0)), Vec3(0.6f, 0.8f, 0));
  expectNear(Transform::rotate(Vec3(0.6f, 0.8f, 0), 90).vector(Vec3(0, 0, 1)), Vec3(0.8f, -0.6f, 0));
}

TEST(Transform, LookAtMapsCameraAxes) {
  Vec3 origin(1, 2, 3), target(4, 6, 3);
  Transform t = Transform::lookAt(origin, target, Vec3(0, 0, 1));
  expectNear(t.point(Vec3(0, 0, 0)), origin);
  expectNear(t.vector(Vec3(0, 0, 1)), Vec3(0.6f, 0.8f, 0));
  expectNear(t.vector(Vec3(0, 1, 0)), Vec3(0, 0, 1));
  // left = up x dir.
  expectNear(t.vector(Vec3(1, 0, 0)), Vec3(-0.8f, 0.6f, 0));
}

TEST(Transform, InverseRoundTrips) {
  Transform t = general();
  Matrix4 product = (t * t.inverse()).matrix();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(product.m[i][j], i == j ? 1.0 : 0.0, 1e-9);
  Vec3 p(0.7f, -1.2f, 4);
  expectNear(t.inverse().point(t.point(p)), p, 1e-4f);
  // The stored inverse agrees with a fresh inversion of the matrix.
  Matrix4 inv = t.matrix().inverse();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(t.inverseMatrix().m[i][j], inv.m[i][j], 1e-9);
}

TEST(Transform, NormalsStayPerpendicularToTangents) {
  Transform t = general();
  Vec3 n = normalize(Vec3(1, 1, 0)), tangent = Vec3(1, -1, 0.5f);
  EXPECT_NEAR(dot(t.normal(n), t.vector(tangent)), 0.0f, 1e-5f);
}
