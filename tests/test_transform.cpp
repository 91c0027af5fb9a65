#include <gtest/gtest.h>

#include "core/transform.h"

using namespace columba;

namespace {

void expectNear(const Vec3& a, const Vec3& b, float tol = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

Transform general() {
  return Transform::translate(Vec3(0.3f, -2, 5)) * Transform::rotate(Vec3(1, 2, -0.5f), 37) *
         Transform::scale(Vec3(2, 0.5f, 3)) * Transform::lookAt(Vec3(1, 2, 3), Vec3(-1, 0, 0.5f), Vec3(0, 0, 1));
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
